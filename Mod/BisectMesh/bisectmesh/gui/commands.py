"""Every BisectMesh command, registered when FreeCAD's GUI starts, BisectMesh's place in the
FEM workbench, and the rest of what starts with the GUI (preferences page, view watch).

InitGui.py imports this module at start-up, so the commands exist in every workbench from the
first moment (not only once the BisectMesh workbench has been activated). The commands' modules
import FreeCAD and nothing heavy: the compiled core and Qt load when a command first runs.

The FEM workbench of FreeCAD 0.20 gets:
- a **BisectMesh toolbar**, stored the way FreeCAD stores a user's custom toolbar (Tools >
  Customize > Toolbars): a group under ``User parameter:BaseApp/Workbench/FemWorkbench/Toolbar``
  with ``Name`` = "BisectMesh", ``Active`` and one string per command (command name -> the module
  that registers it, which FreeCAD imports when the command is missing). FreeCAD builds it on
  every activation of the FEM workbench. It is added once; a user who deletes it in Customize
  keeps it deleted (``FemToolbarAdded`` in BisectMesh's preferences);
- the same commands at the end of FEM's **Mesh menu**: FreeCAD 0.20 stores no custom menus, so
  they are appended to the menu each time the main window reports the FEM workbench activated
  (its ``workbenchActivated`` signal comes after FreeCAD has built the workbench's menus).
"""

import FreeCAD

from . import command_mesh, command_quality, command_region, command_remesh

# in toolbar and menu order
COMMANDS = (command_mesh.COMMAND_NAME, command_remesh.COMMAND_NAME, command_region.COMMAND_NAME,
            command_quality.COMMAND_NAME)
_REGISTER = (command_mesh.register, command_remesh.register, command_region.register, command_quality.register)

FEM_WORKBENCH = "FemWorkbench"
TOOLBAR_NAME = "BisectMesh"
FEM_TOOLBARS = "User parameter:BaseApp/Workbench/%s/Toolbar" % FEM_WORKBENCH
PREFERENCES = "User parameter:BaseApp/Preferences/Mod/BisectMesh"
_MODULE = __name__  # what FreeCAD imports when a toolbar's command is not registered yet
FEM_MESH_MENU = "M&esh"  # the objectName FreeCAD gives the menu: its untranslated text


def register_all():
    """Registers every command with FreeCAD (again after a reload: the newest proxies win)."""
    for register in _REGISTER:
        register()


def fem_toolbar_group():
    """The parameter group of BisectMesh's toolbar in the FEM workbench, or None. Found by its
    Name, since FreeCAD's Customize dialog renumbers the groups (Custom_1, Custom_2, ...)."""
    toolbars = FreeCAD.ParamGet(FEM_TOOLBARS)
    for group_name in toolbars.GetGroups():
        group = toolbars.GetGroup(group_name)
        if group.GetString("Name") == TOOLBAR_NAME:
            return group
    return None


def install_fem_toolbar():
    """Adds (the first time) or updates BisectMesh's toolbar in the FEM workbench; returns its
    parameter group, or None when the user has removed it."""
    prefs = FreeCAD.ParamGet(PREFERENCES)
    group = fem_toolbar_group()
    if group is None:
        if prefs.GetBool("FemToolbarAdded", False):
            return None  # removed by the user: leave it so
        toolbars = FreeCAD.ParamGet(FEM_TOOLBARS)
        taken = set(toolbars.GetGroups())
        number = 1
        while "Custom_%d" % number in taken:
            number += 1
        group = toolbars.GetGroup("Custom_%d" % number)
        group.SetString("Name", TOOLBAR_NAME)
        group.SetBool("Active", True)
        prefs.SetBool("FemToolbarAdded", True)
    # this version's commands, in order: an older version's list is replaced, Active is kept
    for kind, name, _value in group.GetContents() or []:
        if kind == "String" and name != "Name":
            group.RemString(name)
    for name in COMMANDS:
        group.SetString(name, _MODULE)
    return group


def add_to_fem_menu(workbench_name):
    """Slot of the main window's workbenchActivated: appends the commands to FEM's Mesh menu."""
    if workbench_name != FEM_WORKBENCH:
        return
    import FreeCADGui
    from PySide import QtGui

    window = FreeCADGui.getMainWindow()
    menu = None
    for candidate in window.menuBar().findChildren(QtGui.QMenu):
        if candidate.objectName() == FEM_MESH_MENU:
            menu = candidate
            break
    if menu is None:
        return
    present = set(menu.actions())
    actions = []
    for name in COMMANDS:
        command = FreeCADGui.Command.get(name)
        actions.extend(a for a in (command.getAction() if command else []) if a not in present)
    if actions:
        menu.addSeparator()
        for action in actions:
            menu.addAction(action)


_connected = []


def connect_fem_menu():
    """Connects add_to_fem_menu to the main window once (a second InitGui run does not double it)."""
    if _connected:
        return
    import FreeCADGui

    FreeCADGui.getMainWindow().workbenchActivated.connect(add_to_fem_menu)
    _connected.append(True)


def set_up_at_start():
    """What InitGui.py runs after importing this module (which registered the commands): the FEM
    toolbar and the FEM menu entries, the preferences page, the watch on the Parts' view
    resolution (view_watch.py), and one line in the report view when the compiled module is
    missing. Each part on its own: one failing does not stop the others."""
    from . import report_core_problem

    for step in (install_fem_toolbar, connect_fem_menu, _preferences_page, _view_watch, report_core_problem):
        try:
            step()
        except Exception as err:  # FreeCAD must start whatever happens here
            FreeCAD.Console.PrintError("BisectMesh: %s failed at start-up: %s\n" % (step.__name__.strip("_"), err))


def _preferences_page():
    from . import preferences_page

    preferences_page.register()


def _view_watch():
    from . import view_watch

    view_watch.install()


# Importing this module registers the commands: InitGui.py does at start-up, and FreeCAD does when
# it builds the FEM toolbar and finds a command missing (the toolbar names this module).
if FreeCAD.GuiUp:
    register_all()
