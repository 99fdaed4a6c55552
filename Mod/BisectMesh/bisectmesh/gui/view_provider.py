"""The view provider proxy of the BisectMesh mesh object (bisectmesh.mesh_object): its icon (greyed
with a warning badge while the mesh needs a re-mesh) and the mesh panel on double-click or Edit.
Documents saved before it moved here name it bisectmesh.mesh_object.ViewProviderMeshObject,
which that module still resolves.
"""


class ViewProviderMeshObject:
    """View provider proxy: our icon, and the mesh panel on double-click or Edit. The mesh itself
    is drawn by FEM's ViewProviderFemMeshPython, which this proxy extends."""

    def __init__(self, vobj):
        vobj.Proxy = self

    def attach(self, vobj):
        self.Object = vobj.Object

    def getIcon(self):
        from . import icon_path

        obj = getattr(self, "Object", None)
        stale = obj is not None and getattr(obj, "NeedsRemesh", False)
        return icon_path("BisectMesh_MeshStale.svg" if stale else "BisectMesh_Mesh.svg")

    def claimChildren(self):
        # the mesh regions show under the mesh, as under FreeCAD's Gmsh object
        obj = getattr(self, "Object", None)
        return list(getattr(obj, "MeshRegionList", None) or [])

    def setEdit(self, vobj, mode=0):
        if mode != 0:
            return None  # other edit modes (Transform, ...) stay FreeCAD's
        import FreeCADGui
        from . import mesh_panel

        obj = vobj.Object
        if obj.Part is None:
            import FreeCAD

            FreeCAD.Console.PrintError("BisectMesh: %s has no Part to mesh; set its Part property\n" % obj.Label)
            return False
        FreeCADGui.Control.showDialog(mesh_panel.MeshPanel(obj.Part, mesh_obj=obj))
        return True

    def unsetEdit(self, vobj, mode=0):
        if mode != 0:
            return None
        import FreeCADGui

        FreeCADGui.Control.closeDialog()
        return True

    def doubleClicked(self, vobj):
        import FreeCADGui

        gui_doc = FreeCADGui.getDocument(vobj.Object.Document.Name)
        if gui_doc.getInEdit() or FreeCADGui.Control.activeDialog():
            import FreeCAD

            FreeCAD.Console.PrintWarning("BisectMesh: close the open task dialog first\n")
            return True
        gui_doc.setEdit(vobj.Object.Name, 0)
        return True

    def __getstate__(self):
        return None

    def __setstate__(self, state):
        return None
