# BisectMesh: the workbench, registered when FreeCAD's GUI starts.
#
# FreeCAD runs this file through exec(); names defined at its top level are not visible inside
# the methods below, so each method imports what it needs.
#
# The commands are registered here, at start-up, not in Initialize(): they exist in every
# workbench from the start, and the FEM workbench gets a BisectMesh toolbar and its Mesh menu the
# BisectMesh commands (bisectmesh/gui/commands.py says how).
#
# Without its compiled module (bisectmesh._core not built or not installed) the workbench still
# loads: one line in the report view names the command that builds it, and the commands stay
# greyed out, saying the same in their tooltips. Nothing here imports the compiled module.

import FreeCAD
import FreeCADGui

try:
    from bisectmesh.gui import commands as _bisectmesh_commands

    _bisectmesh_commands.set_up_at_start()
except Exception as _err:  # FreeCAD must start whatever happens here
    FreeCAD.Console.PrintError("BisectMesh: the commands could not be registered: %s\n" % _err)


class BisectMeshWorkbench(FreeCADGui.Workbench):
    """Tetrahedral meshing by domain bisection, and mesh quality for FEM meshes."""

    MenuText = "BisectMesh"
    ToolTip = "Tetrahedral meshes by domain bisection; quality of FEM meshes"

    def __init__(self):
        from bisectmesh.gui import icon_path

        self.__class__.Icon = icon_path("BisectMesh.svg")

    def Initialize(self):
        from bisectmesh.gui import commands, report_core_problem

        report_core_problem(load=True)  # one line, once, if the compiled module cannot be loaded
        self.appendToolbar("BisectMesh", list(commands.COMMANDS))
        self.appendMenu("&BisectMesh", list(commands.COMMANDS))

    def Activated(self):
        pass

    def Deactivated(self):
        pass

    def ContextMenu(self, recipient):
        from bisectmesh.gui import command_mesh, command_quality, command_region, command_remesh

        if recipient != "Tree":
            return
        if command_mesh.selected_solid() is not None:
            self.appendContextMenu("", [command_mesh.COMMAND_NAME])
        if command_remesh.selected_mesh_object() is not None:
            self.appendContextMenu("", [command_remesh.COMMAND_NAME, command_region.COMMAND_NAME])
        if command_quality.selected_fem_mesh() is not None:
            self.appendContextMenu("", [command_quality.COMMAND_NAME])

    def GetClassName(self):
        return "Gui::PythonWorkbench"


FreeCADGui.addWorkbench(BisectMeshWorkbench())
