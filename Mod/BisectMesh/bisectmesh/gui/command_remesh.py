"""The "Re-mesh" command: meshes the selected BisectMesh mesh object again, from its current
Part and parameters, in the mesh panel's worker thread (progress bar, Stop); the panel closes and
the object takes the mesh when it is done. A document recompute never does this by itself."""

import FreeCAD

from . import SelectionCommand

COMMAND_NAME = "BisectMesh_Remesh"
_TOOLTIP = ("Re-mesh: meshes the selected BisectMesh mesh object again from its Part and its "
            "parameters, with a progress bar and Stop (a recompute only marks it as needing it)")


def selected_mesh_object():
    """The one selected BisectMesh mesh object, or None."""
    import FreeCADGui

    from .. import mesh_object

    selection = FreeCADGui.Selection.getSelection()
    if len(selection) == 1 and mesh_object.is_mesh_object(selection[0]):
        return selection[0]
    return None


def why_inactive():
    """'' when the command can run; otherwise what the user should do first."""
    import FreeCADGui

    if FreeCAD.ActiveDocument is None:
        return "Open a document with a BisectMesh mesh object, and select it"
    obj = selected_mesh_object()
    if obj is None:
        return "Select one BisectMesh mesh object in the tree view"
    if obj.Part is None:
        return "%s has no Part to mesh; set its Part property" % obj.Label
    if FreeCADGui.Control.activeDialog():
        return "Close the open task dialog first"
    return ""


def remesh_in_panel(obj):
    """Opens the mesh panel on ``obj`` and starts meshing at once; OK is pressed for the user
    when the mesh is ready (Stop or Cancel leave the object as it was). Returns the panel."""
    import FreeCADGui

    from . import mesh_panel

    panel = mesh_panel.MeshPanel(obj.Part, mesh_obj=obj)
    FreeCADGui.Control.showDialog(panel)
    panel.start()
    panel.accept_when_done()
    return panel


class RemeshCommand(SelectionCommand):
    """Re-mesh the selected BisectMesh mesh object."""

    COMMAND_NAME = COMMAND_NAME
    ICON = "BisectMesh_Mesh.svg"
    MENU_TEXT = "Re-mesh"
    TOOLTIP = _TOOLTIP
    NEEDS = "Select a BisectMesh mesh object first."

    def why_inactive(self):
        return why_inactive()

    def Activated(self):
        obj = selected_mesh_object()
        if obj is None or why_inactive():
            return
        remesh_in_panel(obj)


def register():
    import FreeCADGui

    FreeCADGui.addCommand(COMMAND_NAME, RemeshCommand())
