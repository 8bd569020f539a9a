#!/usr/bin/env python3
"""CTest python_pip_install: `pip install --no-build-isolation --no-deps <source>` into a fresh virtual environment
with the system site packages (Debian's NumPy, matplotlib, setuptools), then the two examples run with that
environment's interpreter from a temporary folder outside the source and build trees, so that `import conforma`
can only find the installed package (checked), and the scenario comes from the package's share/.

    pip_install_check.py --source DIR --cmake-build-dir DIR [--python PY] [--jobs 2] [--shared-data DIR] [--keep]

--cmake-build-dir is handed to setup.py as CONFORMA_PIP_BUILD_DIR (kept between runs: the CMake build is
incremental); ccache is used when on PATH. Exit 77 (CTest: skipped) when python3-venv or pip is missing, with the
reason on stdout; any other failure exits 1.
"""
import argparse
import os
import pathlib
import shlex
import shutil
import subprocess
import sys
import tempfile
import time

SKIP = 77


def run(command, **kwargs):
    print("+", " ".join(str(c) for c in command), flush=True)
    return subprocess.run([str(c) for c in command], **kwargs)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--source", required=True, type=pathlib.Path)
    parser.add_argument("--cmake-build-dir", required=True, type=pathlib.Path)
    parser.add_argument("--python", default=sys.executable, help="interpreter the virtual environment is made from")
    parser.add_argument("--jobs", default="2", help="parallel compile jobs of the CMake build")
    parser.add_argument("--shared-data", help="CONFORMA_SHARED_DATA of the package's build (the built-in default "
                                               "of conforma.default_shared_data)")
    parser.add_argument("--keep", action="store_true", help="keep the temporary folder (venv, example outputs)")
    args = parser.parse_args()
    source = args.source.resolve()

    probe = run([args.python, "-c", "import venv, ensurepip"], capture_output=True, text=True)
    if probe.returncode != 0:
        print(f"SKIPPED: {args.python} cannot make a virtual environment with pip (Debian package python3-venv "
              f"missing: {probe.stderr.strip().splitlines()[-1] if probe.stderr.strip() else 'no ensurepip'})")
        return SKIP

    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "PYTHONHOME", "CONFORMA_SHARE_DIR",
                                                            "PIP_REQUIRE_VIRTUALENV", "PIP_USER")}
    env.update(CONFORMA_PIP_BUILD_DIR=str(args.cmake_build_dir.resolve()), CMAKE_BUILD_PARALLEL_LEVEL=args.jobs,
               PIP_NO_INDEX="1", PIP_DISABLE_PIP_VERSION_CHECK="1", MPLBACKEND="Agg")
    if args.shared_data:
        env["CONFORMA_CMAKE_ARGS"] = shlex.join([f"-DCONFORMA_SHARED_DATA={args.shared_data}"])
    work = pathlib.Path(tempfile.mkdtemp(prefix="conforma-pip-install-"))
    try:
        venv = work / "venv"
        made = run([args.python, "-m", "venv", "--system-site-packages", venv], env=env, capture_output=True,
                   text=True)
        if made.returncode != 0:
            print(made.stdout, made.stderr)
            if "ensurepip" in made.stdout + made.stderr:
                print("SKIPPED: the virtual environment has no pip (Debian package python3-venv missing)")
                return SKIP
            return 1
        py = venv / "bin" / "python"
        if run([py, "-m", "pip", "--version"], env=env).returncode != 0:
            print("SKIPPED: no pip in the virtual environment (Debian packages python3-pip / python3-venv)")
            return SKIP

        start = time.monotonic()
        run([py, "-m", "pip", "install", "--no-build-isolation", "--no-deps", source], env=env, check=True)
        print(f"pip install: {time.monotonic() - start:.1f} s", flush=True)

        # run from a folder outside the source and build trees, with copies of the examples: only the installed
        # package can be imported, and the examples' default scenario comes from the package's share/
        outside = work / "run"
        outside.mkdir()
        for name in ["conformal_vs_hertz.py", "wear_sd_sh_qr.py"]:
            shutil.copy2(source / "examples" / name, outside / name)
        site = run([py, "-c", "import conforma, sys; print(conforma.__file__); print(conforma.share_dir()); "
                              "print(conforma.scenario_path())"],
                   env=env, cwd=outside, check=True, capture_output=True, text=True).stdout.split("\n")
        package_file, share, scenario = (pathlib.Path(s).resolve() for s in site[:3])
        prefix = venv.resolve()
        for what, path in [("conforma", package_file), ("share_dir()", share), ("scenario_path()", scenario)]:
            if prefix not in path.parents:
                print(f"FAILED: {what} is {path}, not inside the virtual environment {prefix}")
                return 1
        for name in ["py.typed", "__init__.pyi", "_core.pyi"]:
            if not (package_file.parent / name).is_file():
                print(f"FAILED: {name} was not installed with the package ({package_file.parent})")
                return 1

        out = outside / "out"
        run([py, outside / "conformal_vs_hertz.py", "--output-dir", out], env=env, cwd=outside, check=True)
        run([py, outside / "wear_sd_sh_qr.py", "--output-dir", out, "--model", "hertz", "--steps", "3"], env=env,
            cwd=outside, check=True)
        for name in ["conformal_vs_hertz.png", "wear_sd_sh_qr.png", "wear_sd_sh_qr.csv"]:
            if not (out / name).is_file() or (out / name).stat().st_size == 0:
                print(f"FAILED: the examples did not write {out / name}")
                return 1
        rows = (out / "wear_sd_sh_qr.csv").read_text().strip().splitlines()
        if len(rows) != 1 + 4:  # header, the initial wheel and 3 steps
            print(f"FAILED: wear_sd_sh_qr.csv has {len(rows)} lines, expected 5")
            return 1
        print(f"python_pip_install: installed into {prefix} and ran both examples "
              f"({time.monotonic() - start:.1f} s from pip install on)")
        return 0
    finally:
        if args.keep:
            print(f"kept {work}")
        else:
            shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
