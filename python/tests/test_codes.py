"""The package's codes against the C header it calls through (include/hillstab.h): methods,
samplings, error codes, NEED_*, the values' indices, the system verdicts and kinds, the methods
systems take. (The Fortran suite `codes` checks both against the Fortran tables.)"""
import os
import re

from hillstab import _capi, system
from hillstab import ALIASES, ALL_VALUES

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
HEADER = os.path.join(ROOT, "include", "hillstab.h")


def header_codes():
    """Every enumerator HILLSTAB_<NAME> = <code> of the header, by NAME."""
    text = open(HEADER, encoding="utf-8").read()
    return {name: int(code) for name, code in re.findall(r"\bHILLSTAB_([A-Z0-9_]+) = (-?\d+)", text)}


def group(prefix):
    """The header's codes whose names start with prefix, by the rest of the name."""
    return {name[len(prefix):]: code for name, code in header_codes().items() if name.startswith(prefix)}


def test_methods_and_samplings():
    assert _capi.METHODS == {name.lower(): code for name, code in group("METHOD_").items()}
    assert _capi.SAMPLINGS == {name.lower(): code for name, code in group("SAMPLING_").items()}


def test_error_codes():
    python = {name[len("ERR_"):]: getattr(_capi, name) for name in dir(_capi) if name.startswith("ERR_")}
    assert python == group("ERR_")


def test_needs():
    python = {name[len("NEED_"):]: getattr(_capi, name) for name in dir(_capi) if name.startswith("NEED_")}
    assert python == group("NEED_")


def test_values_in_order_of_their_index():
    values = group("VALUE_")
    count = values.pop("COUNT")
    assert _capi.VALUE_COUNT == count == len(_capi.VALUES)
    # the files' names (HILLSTAB_VALUE_S, _MU, ...) are aliases of the earlier ones' indices
    aliases = {ALIASES[name].upper(): _capi.VALUES.index(name) for name in ALIASES}
    assert {name: values.pop(name) for name in aliases} == aliases
    assert {name.upper(): index for index, name in enumerate(_capi.VALUES)} == values


def test_values_by_the_files_names_in_the_header():
    """Every value Python names is a HILLSTAB_VALUE_* of the same index, by the same name."""
    values = group("VALUE_")
    for name in ALL_VALUES:
        if name == "log_moduli":
            continue
        assert name.upper() in values
    assert values["S"] == values["TRACE"] and values["MU"] == values["EXPONENT"]
    assert values["LOG10_ABS_S"] == values["LOG10_ABS_TRACE"] and values["LOG_ABS_S"] == values["LOG_ABS_TRACE"]


def test_system_verdicts_and_kinds():
    verdicts = {name[len("VERDICT_"):]: getattr(system, name) for name in dir(system) if name.startswith("VERDICT_")}
    kinds = {name[len("KIND_"):]: getattr(system, name) for name in dir(system)
             if name.startswith("KIND_") and name != "KIND_NAMES"}
    assert verdicts == group("SYSTEM_VERDICT_")
    assert kinds == group("SYSTEM_KIND_")
    assert sorted(system.KIND_NAMES) == sorted(kinds.values())
    assert system.KIND_UNDECIDED == 5


def test_system_methods_are_the_headers():
    text = " ".join(open(HEADER, encoding="utf-8").read().replace("*", " ").split())
    listed = re.search(r"Methods: (HILLSTAB_METHOD_[A-Z0-9_, ]+(?: or _[A-Z0-9]+));", text).group(1)
    names = [name.lower() for name in re.findall(r"_([A-Z0-9]+)(?:,| or|$)", listed)]
    assert list(system.SYSTEM_METHODS) == names
    assert all(system.SYSTEM_METHODS[name] == _capi.METHODS[name] for name in names)


def test_region_kinds_and_statuses():
    from hillstab import curves
    python = {name[len("REGION_"):]: getattr(curves, name) for name in dir(curves)
              if name.startswith("REGION_") and not name.endswith("_NAMES")}
    assert python == group("REGION_")
    kinds = {name: code for name, code in python.items() if code in (0, 1, 2, 3) and name in (
        "UNASSIGNED", "SIMPLE", "SUM", "DIFFERENCE")}
    assert {code: name.lower() for name, code in kinds.items()} == curves.REGION_KIND_NAMES
    statuses = {name: code for name, code in python.items() if name not in kinds}
    assert {code: name.lower().replace("_", " ") for name, code in statuses.items()} == curves.REGION_STATUS_NAMES
