"""No silent failures: a result whose solve did not converge or failed is flagged in the result itself
(``complete``, ``problems``) and, unless the caller asked for strictness, with an ``IncompleteResultWarning``.

The statuses come from the C++ core (the keys of `conforma contact --json`):
  wheel ``status``          "ok" | "no_contact" (physics: the wheel does not touch its rail; incomplete under a
                            positive prescribed load, which it does not carry) | "not_converged"
                            (the load control did not reach the load: the forces are those of the last iterate)
  patch ``normal_status``   complete: "ok", "hertz_regularised" (Hertz with B raised to 0.1 A, a documented
                            regularisation); anything else is incomplete: "contact_at_patch_boundary" (the patch was
                            cut at the end of its strips), "load_not_reached", "no_bracket", "not_converged",
                            "no_equivalent_ellipse", "influence_not_positive", "no_solution", ...
  patch ``tangential_status`` complete: "ok", "full_slip", "no_creepage", "not_solved" (the normal-only reference
                            model); anything else (e.g. "no_contact") is incomplete
  wear ``status``           "completed" is complete; "invalid_profile" / "no_wear" stopped the run early; a step
                            with failed contacts (no wear taken from them) makes the run partial.
A status not listed as complete counts as incomplete, so a status added to the core later is not silently accepted.
"""
import warnings

NORMAL_COMPLETE = frozenset({"ok", "hertz_regularised"})
TANGENTIAL_COMPLETE = frozenset({"ok", "full_slip", "no_creepage", "not_solved"})
WHEEL_COMPLETE = frozenset({"ok", "no_contact"})


class IncompleteResultWarning(UserWarning):
    """A result is returned, but a solve in it did not converge or failed (see the result's ``problems``).
    Turn it into an error with ``warnings.simplefilter("error", conforma.IncompleteResultWarning)`` or pass
    ``strict=True``."""


class IncompleteResultError(RuntimeError):
    """Raised instead of IncompleteResultWarning when ``strict=True``; ``.result`` holds the (partial) result and
    ``.problems`` the list of what is missing."""

    def __init__(self, message, result, problems):
        super().__init__(message)
        self.result = result
        self.problems = problems


def _field(result, key, what):
    """result[key], or a ValueError naming what the dict was expected to be (a user's own dict, a wrong object)."""
    if not isinstance(result, dict):
        raise TypeError(f"{what}: expected a dict, got {type(result).__name__}")
    if key not in result:
        raise ValueError(f"{what}: the dict has no '{key}' (keys: {sorted(result)[:8]})")
    return result[key]


def wheel_problems(wheel, load_N=None):
    """What is incomplete in one wheel dict of contact() / contact_at_pose(): a list of strings ([] = complete).
    load_N: the prescribed wheel load (None or < 0: pose given); a wheel without contact under a positive load did
    not carry it (the rule of `conforma contact`, src/app/contact_status.hpp)."""
    what = "wheel_problems: a wheel dict of contact() / contact_at_pose() / ContactLut.evaluate()"
    status = _field(wheel, "status", what)
    side = wheel.get("side", "?")
    problems = []
    if status == "no_contact" and load_N is not None and load_N > 0:
        problems.append(f"{side} wheel: status no_contact: the prescribed load {load_N:.6g} N is not carried")
    elif status not in WHEEL_COMPLETE:
        problems.append(f"{side} wheel: status {status} (vertical pressure force "
                        f"{wheel.get('pressure_vertical_force_N', float('nan')):.6g} N)")
    for j, p in enumerate(wheel.get("patches", [])):
        normal = _field(p, "normal_status", f"{what}, patch {j}")
        tangential = _field(p, "tangential_status", f"{what}, patch {j}")
        if normal not in NORMAL_COMPLETE:
            problems.append(f"{side} wheel, patch {j}: normal_status {normal}")
        if tangential not in TANGENTIAL_COMPLETE:
            problems.append(f"{side} wheel, patch {j}: tangential_status {tangential}")
    return problems


def wear_problems(run):
    """What is incomplete in a wear() result: a list of strings ([] = complete). The rule of `conforma wear`
    (IncompleteReason, include/conforma/wear_simulation.hpp): a status other than "completed", or wheel contacts that
    failed (no wear taken from them). Kinematics fallbacks (the steps table's kinematics_fallbacks) are counted in
    the table but are not a missing result."""
    what = "wear_problems: the dict of wear()"
    problems = []
    steps = _field(run, "steps", what)
    for key in ("step", "failed_contacts"):
        _field(steps, key, what + ", 'steps'")
    if _field(run, "status", what) != "completed":
        problems.append(f"status {run['status']} after {len(steps['step']) - 1} step(s): {run.get('message', '')}")
    failed = [(int(steps["step"][i]), int(v)) for i, v in enumerate(steps["failed_contacts"]) if v > 0]
    if failed:
        listed = ", ".join(f"{k} ({v})" for k, v in failed)
        problems.append(f"{sum(v for _, v in failed)} wheel contact(s) failed (no wear taken from them) in "
                        f"step(s) {listed}")
    return problems


def flag(result, problems, what, strict, stacklevel=3):
    """Marks `result` (a dict, or each dict of a list) complete or not; warns, or raises when strict."""
    if not problems:
        return result
    message = f"{what}: incomplete result: " + "; ".join(problems)
    if strict:
        raise IncompleteResultError(message, result, problems)
    warnings.warn(message, IncompleteResultWarning, stacklevel=stacklevel)
    return result
