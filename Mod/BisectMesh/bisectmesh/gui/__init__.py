"""The FreeCAD GUI side of BisectMesh: commands and task panels.

Only the modules that draw widgets need FreeCADGui and Qt; :mod:`.colouring` and
:mod:`.histograms` compute what they show and import without a GUI.
"""

import os

_PACKAGE_DIR = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def icon_path(name):
    """Full path of an icon of ours, e.g. ``icon_path("BisectMesh_Quality.svg")``.

    Installed (and staged in the build tree) the icons sit in ``Mod/BisectMesh/icons``; in the
    source tree they are in the repository's top-level ``icons`` folder."""
    mod_dir = os.path.dirname(_PACKAGE_DIR)
    for folder in (os.path.join(mod_dir, "icons"),
                   os.path.join(mod_dir, os.pardir, os.pardir, "icons")):
        candidate = os.path.normpath(os.path.join(folder, name))
        if os.path.isfile(candidate):
            return candidate
    return ""


_core_state = {}


def core_missing():
    """'' when the compiled module bisectmesh._core is there, else one line saying it is not and
    which command builds it. Only looked for (not loaded: cheap enough for IsActive, and FreeCAD's
    start-up loads nothing of BisectMesh's core); remembered for the session."""
    if "missing" not in _core_state:
        import importlib.util

        import bisectmesh

        try:
            found = importlib.util.find_spec("bisectmesh._core") is not None
        except (ImportError, ValueError):
            found = False
        _core_state["missing"] = "" if found else (
            "the compiled module bisectmesh._core is missing from %s: build and install it with %s in "
            "BisectMesh's source folder, then restart FreeCAD" % (_PACKAGE_DIR, bisectmesh.SETUP_COMMAND))
    return _core_state["missing"]


def report_core_problem(load=False):
    """Prints, once per session, one line in the report view when the compiled module is missing
    or (``load``: it is imported) cannot be loaded; returns that line, or ''."""
    problem = core_missing()
    if not problem and load:
        import bisectmesh

        problem = bisectmesh.core_problem()
        _core_state["missing"] = problem  # the commands grey out too
    if problem and not _core_state.get("reported"):
        import FreeCAD

        FreeCAD.Console.PrintError("BisectMesh: %s. Its commands stay greyed out until then.\n" % problem)
        _core_state["reported"] = True
    return problem


class SelectionCommand:
    """A toolbar command that acts on the selection and, while greyed out, says in its tooltip
    what the user should select first. Subclasses set COMMAND_NAME, ICON, MENU_TEXT, TOOLTIP
    and NEEDS (the hint in the tooltip), and define why_inactive() ('' when it can run)."""

    COMMAND_NAME = ICON = MENU_TEXT = TOOLTIP = NEEDS = ""

    def __init__(self):
        self._shown_tooltip = None

    def why_inactive(self):
        raise NotImplementedError("a SelectionCommand defines why_inactive")

    def GetResources(self):
        return {"Pixmap": icon_path(self.ICON), "MenuText": self.MENU_TEXT,
                "ToolTip": self.TOOLTIP + ".\n" + self.NEEDS}

    def IsActive(self):
        missing = core_missing()
        reason = missing[:1].upper() + missing[1:] if missing else self.why_inactive()
        self._show_tooltip(self.TOOLTIP + "." if not reason else reason + ".\n\n" + self.TOOLTIP + ".")
        return not reason

    def _show_tooltip(self, text):
        # FreeCAD's commands carry a fixed tooltip; updating the QAction makes the greyed-out
        # button tell the user what is missing. IsActive runs often, so only on a change.
        if text == self._shown_tooltip:
            return
        try:
            import FreeCADGui

            command = FreeCADGui.Command.get(self.COMMAND_NAME)
            actions = command.getAction() if command else []
        except Exception:
            return
        for action in actions:
            action.setToolTip(text)
            action.setStatusTip(text.split("\n")[0])
        if actions:
            self._shown_tooltip = text
