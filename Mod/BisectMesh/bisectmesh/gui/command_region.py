"""The "Mesh region" command: adds a FEM mesh region to the selected BisectMesh mesh object and
opens FEM's own task panel for it (its size, and the faces, edges, vertices or solids it acts on).

FEM's "FEM mesh region" command offers itself on Gmsh meshes only; the region object itself is
the same (ObjectsFem.makeMeshRegion appends it to the mesh's MeshRegionList), and BisectMesh
reads it (bisectmesh/mesh_regions.py)."""

import FreeCAD

from . import SelectionCommand

COMMAND_NAME = "BisectMesh_MeshRegion"
_TOOLTIP = ("Mesh region: a smaller element size on chosen faces, edges, vertices or solids of the "
            "selected BisectMesh mesh's Part (FreeCAD's FEM mesh region)")


def why_inactive():
    """'' when the command can run; otherwise what the user should do first."""
    import FreeCADGui

    from .command_remesh import selected_mesh_object

    if FreeCAD.ActiveDocument is None:
        return "Open a document with a BisectMesh mesh object, and select it"
    obj = selected_mesh_object()
    if obj is None:
        return "Select one BisectMesh mesh object in the tree view"
    if FreeCADGui.Control.activeDialog():
        return "Close the open task dialog first"
    return ""


def add_region(obj):
    """Adds a mesh region to ``obj`` through the console (macros record it) and opens its task
    panel; returns the region."""
    import FreeCADGui

    doc = obj.Document
    doc.openTransaction("Mesh region")
    FreeCADGui.addModule("ObjectsFem")
    FreeCADGui.doCommand("bisectmesh_region = ObjectsFem.makeMeshRegion(FreeCAD.getDocument(%r), "
                         "FreeCAD.getDocument(%r).getObject(%r))" % (doc.Name, doc.Name, obj.Name))
    import __main__

    region = __main__.bisectmesh_region
    doc.commitTransaction()
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.doCommand("FreeCADGui.getDocument(%r).setEdit(%r)" % (doc.Name, region.Name))
    return region


class MeshRegionCommand(SelectionCommand):
    """Add a FEM mesh region to the selected BisectMesh mesh object."""

    COMMAND_NAME = COMMAND_NAME
    ICON = "BisectMesh_Mesh.svg"
    MENU_TEXT = "Mesh region"
    TOOLTIP = _TOOLTIP
    NEEDS = "Select a BisectMesh mesh object first."

    def GetResources(self):
        resources = super().GetResources()
        resources["Pixmap"] = "FEM_MeshRegion"  # FEM's own icon (FemGui's resources)
        return resources

    def why_inactive(self):
        return why_inactive()

    def Activated(self):
        from .command_remesh import selected_mesh_object

        obj = selected_mesh_object()
        if obj is None or why_inactive():
            return
        add_region(obj)


def register():
    import FreeCADGui

    FreeCADGui.addCommand(COMMAND_NAME, MeshRegionCommand())
