# BisectMesh: the workbench, registered when FreeCAD's GUI starts.
#
# FreeCAD runs this file through exec(); names defined at its top level are not visible inside
# the methods below, so each method imports what it needs.

import FreeCADGui


class BisectMeshWorkbench(FreeCADGui.Workbench):
    """Tetrahedral meshing by domain bisection, and mesh quality for FEM meshes."""

    MenuText = "BisectMesh"
    ToolTip = "Tetrahedral meshes by domain bisection; quality of FEM meshes"

    def __init__(self):
        from bisectmesh.gui import icon_path

        self.__class__.Icon = icon_path("BisectMesh.svg")

    def Initialize(self):
        from bisectmesh.gui import command_mesh, command_quality

        command_mesh.register()
        command_quality.register()
        commands = [command_mesh.COMMAND_NAME, command_quality.COMMAND_NAME]
        self.appendToolbar("BisectMesh", commands)
        self.appendMenu("&BisectMesh", commands)

    def Activated(self):
        pass

    def Deactivated(self):
        pass

    def ContextMenu(self, recipient):
        from bisectmesh.gui import command_mesh, command_quality

        if recipient != "Tree":
            return
        if command_mesh.selected_solid() is not None:
            self.appendContextMenu("", [command_mesh.COMMAND_NAME])
        if command_quality.selected_fem_mesh() is not None:
            self.appendContextMenu("", [command_quality.COMMAND_NAME])

    def GetClassName(self):
        return "Gui::PythonWorkbench"


FreeCADGui.addWorkbench(BisectMeshWorkbench())
