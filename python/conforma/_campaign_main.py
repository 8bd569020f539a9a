"""Entry of `conforma campaign run|report` (src/app/cmd_campaign.cpp execs `python3 _campaign_main.py ...`): runs
conforma._campaign.main with this file's folder as the package `conforma` but without its __init__.py, which needs
the compiled extension conforma._core; the campaign modules need only the standard library, PyYAML, matplotlib
(report) and Dask distributed (Dask schedulers)."""
import os
import sys

if __name__ == "__main__":
    here = os.path.dirname(os.path.realpath(__file__))
    # run as a script, this folder is sys.path[0]: its types.py would shadow the standard library's `types`
    if sys.path and os.path.realpath(sys.path[0] or ".") == here:
        del sys.path[0]
    if "types" in sys.modules and os.path.dirname(os.path.realpath(getattr(sys.modules["types"], "__file__", ""))) == here:
        raise SystemExit("conforma campaign: the standard library's types module was shadowed")
    import types

    if "conforma" not in sys.modules:
        package = types.ModuleType("conforma", "conforma (campaign modules only: no conforma._core here)")
        package.__path__ = [here]
        sys.modules["conforma"] = package
    from conforma._campaign import main

    sys.exit(main())
