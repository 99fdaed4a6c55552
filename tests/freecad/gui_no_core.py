"""The workbench loaded without its compiled module, in a real FreeCAD window (CTest:
freecad.gui_no_core).

A copy of the staged workbench without bisectmesh._core, in a temporary folder, replaces the
staged one (InitGui.py run again from the copy, as FreeCAD runs it at start-up), and the
BisectMesh workbench is activated. The report view must get one line naming ./scripts/setup.sh,
once, and no traceback; the commands must be greyed out with that line in their tooltip, even
with a solid selected. Log: $BISECTMESH_ARTIFACTS/gui_no_core.log.
"""

import os
import shutil
import sys
import tempfile

import FreeCAD
import FreeCADGui

HERE = os.path.dirname(os.path.abspath(globals().get("__file__", "tests/freecad/gui_no_core.py")))
sys.path.insert(0, HERE)
from gui_harness import BUILD_MOD, check, command_state, report_view_text, settle, start  # noqa: E402




def load_copy_without_core(folder):
    copy = os.path.join(folder, "BisectMesh")
    shutil.copytree(BUILD_MOD, copy, ignore=shutil.ignore_patterns("_core*", "__pycache__"))
    sys.path.insert(0, copy)
    for name in [n for n in sys.modules if n == "bisectmesh" or n.startswith("bisectmesh.")]:
        del sys.modules[name]
    if "BisectMeshWorkbench" in FreeCADGui.listWorkbenches():
        FreeCADGui.removeWorkbench("BisectMeshWorkbench")
    path = os.path.join(copy, "InitGui.py")
    with open(path) as source:
        exec(compile(source.read(), path, "exec"), {"__name__": "BisectMeshInitGui"})
    return copy


def run():
    import fc_helpers

    FreeCADGui.activateWorkbench("StartWorkbench")
    before = len(report_view_text() or "")
    folder = tempfile.mkdtemp(prefix="bisectmesh-nocore-")
    try:
        copy = load_copy_without_core(folder)
        import bisectmesh

        check(bisectmesh.__file__.startswith(copy), "bisectmesh loaded from the copy without _core")
        FreeCADGui.activateWorkbench("BisectMeshWorkbench")
        settle(300)
        doc = FreeCAD.newDocument("NoCore")
        part = fc_helpers.box_minus_cylinder(doc)
        FreeCADGui.Selection.addSelection(part)
        settle(300)
        active = command_state("BisectMesh_Mesh")[0]
        # the tooltip the button shows (the commands registered again from the copy have no
        # button yet here: ask a proxy what it would set)
        from bisectmesh.gui import command_mesh

        shown = []
        proxy = command_mesh.MeshCommand()
        proxy._show_tooltip = shown.append
        proxy.IsActive()
        tooltip = shown[-1] if shown else ""
        text = (report_view_text() or "")[before:]
        lines = [line for line in text.splitlines() if "./scripts/setup.sh" in line]
        check(len(lines) == 1, "one line in the report view names ./scripts/setup.sh: %r" % lines)
        check("bisectmesh._core" in lines[0] if lines else False, "it names the missing module")
        check("Traceback" not in text and "ImportError" not in text, "no traceback, no ImportError")
        check(not active and "./scripts/setup.sh" in tooltip,
              "Mesh with BisectMesh is greyed out with a solid selected, saying why: %r" % tooltip.split("\n")[0])
        for name in ("BisectMesh_Remesh", "BisectMesh_Quality"):
            check(not command_state(name)[0], "%s greyed out" % name)
        FreeCAD.closeDocument(doc.Name)
    finally:
        shutil.rmtree(folder, ignore_errors=True)


start("gui_no_core", run)
