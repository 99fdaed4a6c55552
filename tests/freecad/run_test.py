"""Runs one tests/freecad/test_*.py module inside FreeCAD, for CTest.

CTest calls ``freecadcmd tests/freecad/run_test.py``. freecadcmd passes no arguments on to a
script and its exit code does not follow the script's, so the settings come in environment
variables and the verdict goes out as one line that CTest matches:

    BISECTMESH-TESTS-OK       every test passed (skips allowed, and listed)
    BISECTMESH-TESTS-FAILED   a failure, an error, or no test at all

Environment:
    BISECTMESH_TEST_MODULE   module to run, e.g. test_quality (required)
    BISECTMESH_BUILD_MOD     the workbench staged in the build tree; put first on sys.path so
                             that `import bisectmesh` is the one just built
    BISECTMESH_TEST_DIR      folder of the test modules (default: this file's folder)
    BISECTMESH_SHARED_DIR, BISECTMESH_CLI, BISECTMESH_ARTIFACTS   read by the tests themselves

Run by hand from the repository root, for example:
    BISECTMESH_TEST_MODULE=test_quality BISECTMESH_BUILD_MOD=/work/build-fc/Mod/BisectMesh \
    BISECTMESH_ARTIFACTS=/work/build-fc/test-artifacts freecadcmd tests/freecad/run_test.py
"""

import os
import sys
import time
import traceback
import unittest

OK_LINE = "BISECTMESH-TESTS-OK"
FAILED_LINE = "BISECTMESH-TESTS-FAILED"


def _put_build_first(build_mod):
    """Makes `import bisectmesh` load the package staged in ``build_mod``, even when FreeCAD
    has already put an installed copy of the workbench on sys.path."""
    build_mod = os.path.abspath(build_mod)
    sys.path[:] = [p for p in sys.path if os.path.abspath(p or ".") != build_mod]
    sys.path.insert(0, build_mod)
    for name in [n for n in sys.modules if n == "bisectmesh" or n.startswith("bisectmesh.")]:
        del sys.modules[name]


def _run():
    module_name = os.environ.get("BISECTMESH_TEST_MODULE", "").strip()
    if not module_name:
        print("run_test.py: set BISECTMESH_TEST_MODULE to the test module to run (e.g. test_quality)")
        return False
    here = os.path.dirname(os.path.abspath(globals().get("__file__", "tests/freecad/run_test.py")))
    test_dir = os.environ.get("BISECTMESH_TEST_DIR") or here
    build_mod = os.environ.get("BISECTMESH_BUILD_MOD")
    if build_mod:
        _put_build_first(build_mod)
    if test_dir not in sys.path:
        sys.path.insert(1 if build_mod else 0, test_dir)

    import bisectmesh

    print("bisectmesh from %s" % os.path.dirname(bisectmesh.__file__))
    if build_mod and not os.path.abspath(bisectmesh.__file__).startswith(os.path.abspath(build_mod)):
        print("run_test.py: bisectmesh was imported from elsewhere than BISECTMESH_BUILD_MOD=%s" % build_mod)
        return False

    suite = unittest.defaultTestLoader.loadTestsFromName(module_name)
    runner = unittest.TextTestRunner(stream=sys.stdout, verbosity=2)
    start = time.time()
    result = runner.run(suite)
    print("%s: %d run, %d failures, %d errors, %d skipped in %.1f s" % (
        module_name, result.testsRun, len(result.failures), len(result.errors),
        len(result.skipped), time.time() - start))
    for test, reason in result.skipped:
        print("SKIPPED %s: %s" % (test.id(), reason))
    if result.testsRun == 0:
        print("run_test.py: %s holds no tests" % module_name)
        return False
    return result.wasSuccessful()


def main():
    try:
        ok = _run()
    except BaseException:  # a broken import or setUpModule must still give a verdict line
        traceback.print_exc(file=sys.stdout)
        ok = False
    print(OK_LINE if ok else FAILED_LINE)
    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(0 if ok else 1)


main()
