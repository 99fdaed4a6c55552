"""The workbench without its compiled module: a copy of the staged package without
bisectmesh._core, in a temporary folder, loaded by another freecadcmd. The package, the mesh
object's module and the GUI's command modules import; the missing module is one line in the
report view (once, however often asked), naming ./scripts/setup.sh, never an ImportError
traceback; the commands grey out and say the same; bisectmesh.core() raises an ImportError whose
one line names the command too."""

import json
import os
import shutil
import subprocess
import tempfile
import unittest

import bisectmesh

SCRIPT = r'''
import json, os, sys
sys.path.insert(0, os.environ["NO_CORE_MOD"])
out = {}
import bisectmesh
out["file"] = bisectmesh.__file__
import bisectmesh.mesh_object, bisectmesh.preferences, bisectmesh.mesh_regions
from bisectmesh import gui
from bisectmesh.gui import commands, command_mesh, command_quality, command_remesh
out["missing"] = gui.core_missing()
out["reported"] = [gui.report_core_problem(load=True) for _ in range(3)]
try:
    bisectmesh.core()
    out["core"] = None
except ImportError as err:
    out["core"] = str(err)
tooltips = []
command = command_mesh.MeshCommand()
command._show_tooltip = tooltips.append
out["active"] = command.IsActive()
out["tooltip"] = tooltips[-1] if tooltips else ""
with open(os.environ["NO_CORE_RESULT"], "w") as f:
    json.dump(out, f)
'''


def run_without_core(broken_core=None):
    """Runs SCRIPT in another freecadcmd on a copy of the staged package without its _core (or,
    with ``broken_core``, a _core.py that raises that ImportError, as a module built for another
    Python or missing an OpenCASCADE library does); returns (its results, its output, the copy's
    folder)."""
    staged = os.path.dirname(os.path.dirname(os.path.abspath(bisectmesh.__file__)))
    folder = tempfile.mkdtemp(prefix="bisectmesh-nocore-")
    try:
        copy = os.path.join(folder, "BisectMesh")
        shutil.copytree(staged, copy, ignore=shutil.ignore_patterns("_core*", "__pycache__"))
        if broken_core:
            with open(os.path.join(copy, "bisectmesh", "_core.py"), "w") as f:
                f.write("raise ImportError(%r)\n" % broken_core)
        script = os.path.join(folder, "no_core.py")
        with open(script, "w") as f:
            f.write(SCRIPT)
        result = os.path.join(folder, "result.json")
        env = dict(os.environ, NO_CORE_MOD=copy, NO_CORE_RESULT=result)
        run = subprocess.run(["freecadcmd", script], env=env, capture_output=True, text=True, timeout=120)
        output = run.stdout + run.stderr
        if not os.path.isfile(result):
            raise AssertionError("the script did not finish:\n" + output[-3000:])
        with open(result) as f:
            return json.load(f), output, copy
    finally:
        shutil.rmtree(folder, ignore_errors=True)


class NoCoreTest(unittest.TestCase):
    def check_one_line(self, out, output, *words):
        self.assertEqual(out["reported"], [out["reported"][0]] * 3)
        lines = [line for line in output.splitlines() if line.startswith("BisectMesh:")]
        self.assertEqual(len(lines), 1, output[-3000:])  # once, however often asked
        self.assertNotIn("Traceback", output)
        for word in ("./scripts/setup.sh",) + words:
            self.assertIn(word, lines[0])
            self.assertIn(word, out["core"])
        self.assertNotIn("\n", out["core"])
        print(lines[0])
        return lines[0]

    def test_workbench_without_its_compiled_module(self):
        out, output, copy = run_without_core()
        self.assertTrue(out["file"].startswith(copy), out["file"])
        self.assertIn("./scripts/setup.sh", out["missing"])
        self.assertIn("bisectmesh._core", out["missing"])
        self.check_one_line(out, output, "bisectmesh._core")
        self.assertFalse(out["active"])
        self.assertIn("./scripts/setup.sh", out["tooltip"])

    def test_a_compiled_module_that_does_not_load(self):
        out, output, _ = run_without_core("libTKernel.so.7: cannot open shared object file")
        self.assertEqual(out["missing"], "")  # there is one ...
        self.check_one_line(out, output, "libTKernel.so.7")  # ... that cannot be loaded
        self.assertFalse(out["active"])  # once known, the commands grey out too
        self.assertIn("libTKernel.so.7", out["tooltip"])


if __name__ == "__main__":
    unittest.main()
