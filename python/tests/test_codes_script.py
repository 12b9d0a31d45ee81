"""scripts/codes.py: the codes of models, methods and values that C, FORTRAN 77 and Python copy
are written from the Fortran tables. A new model, method and value, added to a copy of the tree
as a contributor adds them (a name in `model_names`, a row of `method_table`, a `value_<name>`
constant of capi_batch.f90), reach the header's enums, the F77 argument lines and Python's
METHODS, SYSTEM_METHODS and VALUES with the codes of their places; `--check` fails before the
script has written them and passes after."""
import os
import re
import shutil
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SCRIPT = os.path.join(ROOT, "scripts", "codes.py")
FILES = ("src/hillstab/hill/models.f90", "src/hillstab/integrate/monodromy.f90", "include/hillstab.h",
         "src/hillstab/interop/legacy.f90", "src/hillstab/interop/legacy_external.f90",
         "python/hillstab/_capi.py", "python/hillstab/system.py", "src/hillstab/interop/capi_batch.f90")


def run(root, *options):
    return subprocess.run([sys.executable, SCRIPT, "--root", str(root), *options], capture_output=True, text=True)


def tree(tmp_path):
    for path in FILES:
        os.makedirs(os.path.dirname(tmp_path / path), exist_ok=True)
        shutil.copy(os.path.join(ROOT, path), tmp_path / path)
    return tmp_path


def read(root, path):
    return open(os.path.join(root, path), encoding="utf-8").read()


def test_the_repository_is_as_the_tables_give_it():
    done = run(ROOT, "--check")
    assert done.returncode == 0, done.stderr


def test_a_new_model_and_method_reach_every_copy(tmp_path):
    root = tree(tmp_path)
    models = read(root, FILES[0])
    count = int(re.search(r"model_names\((\d+)\)", models).group(1))
    models = re.sub(r"model_names\(\d+\)", "model_names({})".format(count + 1), models, count=1)
    models = models.replace('"equation"]', '"equation", "newmodel"]', 1)
    open(root / FILES[0], "w", encoding="utf-8").write(models)
    methods = read(root, FILES[1])
    high = int(re.search(r"method_table\(0:(\d+)\)", methods).group(1))
    methods = methods.replace("method_table(0:{})".format(high), "method_table(0:{})".format(high + 1), 1)
    methods = re.sub(r'(method_info_t\("gsl",[^\]]*)\]',
                     r'\1, &\n      method_info_t("newmethod", "a test row", exact=.true., systems=.true.)]',
                     methods, count=1)
    open(root / FILES[1], "w", encoding="utf-8").write(methods)
    values = read(root, FILES[7])
    n_values = int(re.search(r"integer, parameter :: value_count = (\d+)", values).group(1))
    last = "value_{} = {}".format(
        [name for name, index in re.findall(r"value_(\w+) = (\d+)", values) if int(index) == n_values - 1][0],
        n_values - 1)
    values = values.replace(last, "{}, value_newvalue = {}".format(last, n_values), 1)
    values = values.replace("value_count = {}".format(n_values), "value_count = {}".format(n_values + 1), 1)
    open(root / FILES[7], "w", encoding="utf-8").write(values)

    stale = run(root, "--check")
    assert stale.returncode == 1 and "include/hillstab.h" in stale.stderr
    assert run(root).returncode == 0
    assert run(root, "--check").returncode == 0

    header = read(root, "include/hillstab.h")
    assert "HILLSTAB_MODEL_NEWMODEL = {}".format(count + 1) in header
    assert "HILLSTAB_METHOD_NEWMETHOD = {}".format(high + 1) in header
    assert "HILLSTAB_MODEL_ELASTIC = 1" in header and "HILLSTAB_METHOD_AUTO = 0" in header
    assert "HILLSTAB_VALUE_NEWVALUE = {}".format(n_values) in header
    assert "HILLSTAB_VALUE_COUNT = {}".format(n_values + 1) in header
    assert "HILLSTAB_VALUE_S = 0" in header   # the aliases' enum, written by hand, kept
    namespace = {}
    exec(re.search(r"^VALUES = \([^)]*\)", read(root, "python/hillstab/_capi.py"), re.M).group(0), namespace)
    assert namespace["VALUES"][-1] == "newvalue" and len(namespace["VALUES"]) == n_values + 1
    for path in FILES[3:5]:
        text = read(root, path)
        assert "{} newmodel".format(count + 1) in text, path
        assert "{} newmethod".format(high + 1) in text, path
        # HSCHAR documents its own models: left as it was
        assert text.count("{} newmodel".format(count + 1)) == 2, path
    assert '"newmethod": {}'.format(high + 1) in read(root, "python/hillstab/_capi.py")
    assert '"newmethod": {}'.format(high + 1) in read(root, "python/hillstab/system.py")
    # what the script wrote is still a header: the enum closes, every other line is untouched
    before = read(ROOT, "include/hillstab.h").splitlines()
    after = header.splitlines()
    assert len(after) - len(before) in (0, 1, 2)
    generated = ("HILLSTAB_MODEL_", "HILLSTAB_METHOD_", "HILLSTAB_VALUE_")
    assert [line for line in after if not any(g in line for g in generated)] == \
        [line for line in before if not any(g in line for g in generated)]


def test_a_broken_table_is_named(tmp_path):
    root = tree(tmp_path)
    methods = read(root, FILES[1]).replace("method_table(0:", "method_table(0:1", 1)
    open(root / FILES[1], "w", encoding="utf-8").write(methods)
    done = run(root)
    assert done.returncode != 0 and "monodromy.f90" in done.stderr and "rows" in done.stderr
    assert read(root, "include/hillstab.h") == read(ROOT, "include/hillstab.h")
