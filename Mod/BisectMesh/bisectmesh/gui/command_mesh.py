"""The "Mesh with BisectMesh" command: opens the mesh panel for the selected Part object."""

import FreeCAD

from . import SelectionCommand

COMMAND_NAME = "BisectMesh_Mesh"
_TOOLTIP = ("Mesh with BisectMesh: a tetrahedral FEM mesh (tetra4 or tetra10) of the selected "
            "solid, by recursive domain bisection; the mesh object joins the active analysis")


def selected_solid():
    """The one selected object whose shape has a solid (a Part feature, a PartDesign Body, ...),
    or None. FEM meshes have no Shape and are never chosen."""
    import FreeCADGui

    selection = FreeCADGui.Selection.getSelection()
    if len(selection) != 1:
        return None
    obj = selection[0]
    shape = getattr(obj, "Shape", None)
    if shape is None or not hasattr(shape, "Solids") or shape.isNull() or not shape.Solids:
        return None
    return obj


def why_inactive():
    """'' when the command can run; otherwise what the user should do first."""
    import FreeCADGui

    if FreeCAD.ActiveDocument is None:
        return "Open a document with a solid, and select it"
    selection = FreeCADGui.Selection.getSelection()
    if len(selection) != 1:
        return "Select one Part object with a solid in the tree view"
    if selected_solid() is None:
        return "%s has no solid to mesh; select a Part object with a solid" % selection[0].Label
    if FreeCADGui.Control.activeDialog():
        return "Close the open task dialog first"
    return ""


class MeshCommand(SelectionCommand):
    """Mesh the selected solid with BisectMesh."""

    COMMAND_NAME = COMMAND_NAME
    ICON = "BisectMesh_Mesh.svg"
    MENU_TEXT = "Mesh with BisectMesh"
    TOOLTIP = _TOOLTIP
    NEEDS = "Select a Part object with a solid first."

    def why_inactive(self):
        return why_inactive()

    def Activated(self):
        import FreeCADGui
        from . import mesh_panel

        part = selected_solid()
        if part is None or FreeCADGui.Control.activeDialog():
            return
        FreeCADGui.Control.showDialog(mesh_panel.MeshPanel(part))


def register():
    import FreeCADGui

    FreeCADGui.addCommand(COMMAND_NAME, MeshCommand())
