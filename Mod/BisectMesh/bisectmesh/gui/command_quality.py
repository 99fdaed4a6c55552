"""The "Mesh quality" command: opens the quality panel for the selected FEM mesh object."""

import FreeCAD

from . import SelectionCommand

COMMAND_NAME = "BisectMesh_Quality"
_TOOLTIP = ("Mesh quality: checks the tetrahedra of the selected FEM mesh (orientation, "
            "conformity, closed boundary) and shows their dihedral angles, solid angles, "
            "\u03b3 and radius ratio, with histograms and colours in the 3D view")


def selected_fem_mesh():
    """The one selected FEM mesh object (any Fem::FemMeshObject), or None."""
    import FreeCADGui

    selection = FreeCADGui.Selection.getSelection()
    if len(selection) != 1:
        return None
    obj = selection[0]
    if obj.isDerivedFrom("Fem::FemMeshObject"):
        return obj
    return None


def why_inactive():
    """'' when the command can run; otherwise what the user should do first."""
    import FreeCADGui

    if FreeCAD.ActiveDocument is None:
        return "Open a document with a FEM mesh, and select the mesh"
    obj = selected_fem_mesh()
    if obj is None:
        return "Select a FEM mesh object (one) in the tree view"
    if obj.FemMesh.VolumeCount == 0:
        return "The selected FEM mesh has no volume elements; select a 3D (tetrahedral) mesh"
    dialog = FreeCADGui.Control.activeDialog()
    if dialog and not _our_panel_is_open():
        return "Close the open task dialog first"
    return ""


def _our_panel_is_open():
    from . import quality_panel

    return quality_panel.QualityPanel.open_panel is not None


class QualityCommand(SelectionCommand):
    """Mesh quality of the selected FEM mesh object."""

    COMMAND_NAME = COMMAND_NAME
    ICON = "BisectMesh_Quality.svg"
    MENU_TEXT = "Mesh quality"
    TOOLTIP = _TOOLTIP
    NEEDS = "Select a FEM mesh object first."

    def why_inactive(self):
        return why_inactive()

    def Activated(self):
        import FreeCADGui
        from . import quality_panel

        obj = selected_fem_mesh()
        if obj is None:
            return
        if FreeCADGui.Control.activeDialog():
            FreeCADGui.Control.closeDialog()
        panel = quality_panel.QualityPanel(obj)
        FreeCADGui.Control.showDialog(panel)
        panel.compute()


def register():
    import FreeCADGui

    FreeCADGui.addCommand(COMMAND_NAME, QualityCommand())
