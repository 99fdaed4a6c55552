"""What the GUI tests (gui_*.py, run by `xvfb-run freecad tests/freecad/gui_X.py`) share: their
log with its verdict line, checks, turns of the event loop, the staged workbench registered in
place of any installed copy, a command's state, and the layout for screenshots.

Environment: BISECTMESH_BUILD_MOD (the workbench staged in the build tree) and
BISECTMESH_ARTIFACTS (where the log and the screenshots go)."""

import os
import sys
import time
import traceback

import FreeCADGui
from PySide import QtCore, QtGui

BUILD_MOD = os.environ.get("BISECTMESH_BUILD_MOD", "/work/build-lead/Mod/BisectMesh")
ARTIFACTS = os.environ.get("BISECTMESH_ARTIFACTS", "/work/build-lead/test-artifacts")
HERE = os.path.dirname(os.path.abspath(__file__))
_state = {"log": None, "start": time.time()}


def log(text):
    if _state["log"] is not None:
        _state["log"].write(text + "\n")
        _state["log"].flush()
    sys.stdout.write(text + "\n")
    sys.stdout.flush()


def check(condition, what):
    log(("ok    " if condition else "FAIL  ") + "%6.1fs  " % (time.time() - _state["start"]) + what)
    if not condition:
        raise AssertionError(what)


def settle(ms=300):
    loop = QtCore.QEventLoop()
    QtCore.QTimer.singleShot(ms, loop.quit)
    loop.exec_()
    FreeCADGui.updateGui()



def select(obj):
    """Selects obj alone (None: nothing), as a click in the tree would."""
    FreeCADGui.Selection.clearSelection()
    if obj is not None:
        FreeCADGui.Selection.addSelection(obj)
    settle(100)


def dialog_button(which):
    """The task dialog's OK or Cancel button, as the user sees it."""
    for box in FreeCADGui.getMainWindow().findChildren(QtGui.QDialogButtonBox):
        button = box.button(which)
        if button is not None and button.isVisible():
            return button
    return None


def report_view_text():
    """The report view's text; None when the window has no report view."""
    for widget in FreeCADGui.getMainWindow().findChildren(QtGui.QTextEdit):
        if widget.metaObject().className().endswith("ReportOutput"):
            return widget.toPlainText()
    return None

def register_staged_workbench():
    """Makes `import bisectmesh` load the staged package and registers its workbench. An installed
    copy (the user's Mod folder) may have registered an older InitGui.py: the staged one replaces
    it, so that its toolbar and menu are the ones tested."""
    sys.path[:] = [p for p in sys.path if os.path.abspath(p or ".") != os.path.abspath(BUILD_MOD)]
    sys.path.insert(0, BUILD_MOD)
    sys.path.insert(1, HERE)
    for name in [n for n in sys.modules if n == "bisectmesh" or n.startswith("bisectmesh.")]:
        del sys.modules[name]
    if "BisectMeshWorkbench" in FreeCADGui.listWorkbenches():
        FreeCADGui.removeWorkbench("BisectMeshWorkbench")
    path = os.path.join(BUILD_MOD, "InitGui.py")
    with open(path) as source:
        exec(compile(source.read(), path, "exec"), {"__name__": "BisectMeshInitGui"})
    FreeCADGui.activateWorkbench("BisectMeshWorkbench")
    import bisectmesh

    check(os.path.abspath(bisectmesh.__file__).startswith(os.path.abspath(BUILD_MOD)),
          "bisectmesh imported from %s" % os.path.dirname(bisectmesh.__file__))


def command_state(name):
    """(is the command active, the tooltip its button shows)."""
    command = FreeCADGui.Command.get(name)
    actions = command.getAction()
    return command.isActive(), actions[0].toolTip() if actions else ""


def widen_combo_view(width):
    """A fresh FreeCAD profile starts with a narrow combo view; widen it for the screenshots."""
    window = FreeCADGui.getMainWindow()
    for dock in window.findChildren(QtGui.QDockWidget):
        if dock.objectName() in ("Combo View", "Tasks") and dock.isVisible():
            window.resizeDocks([dock], [width], QtCore.Qt.Horizontal)


def start(name, run):
    """Runs ``run()`` once the window is up, after registering the workbench; logs to
    ARTIFACTS/<name>.log, ends with GUI-TESTS-OK or GUI-TESTS-FAILED and quits FreeCAD."""
    os.makedirs(ARTIFACTS, exist_ok=True)
    _state["log"] = open(os.path.join(ARTIFACTS, name + ".log"), "w")

    def main():
        ok = False
        try:
            register_staged_workbench()
            run()
            ok = True
        except Exception:
            log(traceback.format_exc())
        log("GUI-TESTS-OK" if ok else "GUI-TESTS-FAILED")
        _state["log"].close()
        _state["log"] = None
        sys.stdout.flush()
        os._exit(0 if ok else 1)

    QtCore.QTimer.singleShot(1000, main)
