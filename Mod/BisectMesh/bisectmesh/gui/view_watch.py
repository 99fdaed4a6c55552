"""Marks BisectMesh mesh objects as needing a re-mesh when their Part's view resolution changes.

With UseResolutionHints the Part's view Deviation and AngularDeflection are inputs of the mesh.
They are properties of the view provider, not of the document object: changing one touches no
object, so no recompute runs, and the mesh object's own check (mesh_object.check_inputs, run by
execute) would only notice at the next recompute that reaches it.

FreeCAD 0.20 has a GUI document observer whose slotChangedObject sees view properties change,
but it cannot be used: FreeCAD calls it while a view provider is being made, and asks it for its
Python object then, which breaks the making of every Python view provider afterwards ("Cannot add
static property" from doc.addObject) or crashes FreeCAD. So the view resolution is polled: once a
second, on the GUI thread, the Deviation and AngularDeflection of the Part of every mesh object
with UseResolutionHints (found by C++'s findObjects, a few microseconds per document) are
compared with the last seen; on a change the mesh object's inputs are checked at once
(NeedsRemesh, MeshStatus, the greyed icon). The task panel checks them too when it opens.
Installed when FreeCAD's GUI starts (commands.set_up_at_start).
"""

import FreeCAD

INTERVAL_MS = 1000
MESH_TYPE = "Fem::FemMeshObjectPython"


class ViewResolutionWatch:
    """Polls the view resolution of the Parts of the mesh objects with UseResolutionHints."""

    def __init__(self):
        self.seen = {}  # (document name, object name) -> (deviation, angular deflection)

    def poll(self):
        """Checks the mesh objects whose Part's view resolution changed since the last poll;
        returns them."""
        changed = []
        try:
            seen = {}
            for doc in FreeCAD.listDocuments().values():
                for obj in doc.findObjects(Type=MESH_TYPE):
                    resolution = _resolution(obj)
                    if resolution is None:
                        continue
                    key = (doc.Name, obj.Name)
                    seen[key] = resolution
                    before = self.seen.get(key)
                    if before is not None and before != resolution:
                        _check(obj, resolution)
                        changed.append(obj)
            self.seen = seen
        except Exception as err:  # a watch must never disturb the GUI
            FreeCAD.Console.PrintError("BisectMesh: checking the meshes after a view change: %s\n" % err)
        return changed


def _resolution(obj):
    """(Deviation, AngularDeflection) of the view of ``obj``'s Part when ``obj`` is a BisectMesh
    mesh object with UseResolutionHints; else None."""
    from .. import mesh_object

    if not (mesh_object.is_mesh_object(obj) and getattr(obj, "UseResolutionHints", False)):
        return None
    view = getattr(obj.Part, "ViewObject", None) if obj.Part is not None else None
    if view is None or not hasattr(view, "Deviation"):
        return None
    return float(view.Deviation), float(view.AngularDeflection)


def _check(obj, resolution):
    from .. import mesh_object

    mesh_object.check_inputs(obj, reason="the view resolution of %s changed (Deviation %g %%, "
                             "AngularDeflection %g\u00b0)" % ((obj.Part.Label,) + resolution))


_installed = []


def install():
    """Starts the watch once per session; returns it."""
    if not _installed:
        import FreeCADGui
        from PySide import QtCore

        watch = ViewResolutionWatch()
        timer = QtCore.QTimer(FreeCADGui.getMainWindow())
        timer.setObjectName("BisectMeshViewWatch")
        timer.setInterval(INTERVAL_MS)
        timer.timeout.connect(watch.poll)
        timer.start()
        watch.timer = timer
        _installed.append(watch)
    return _installed[0]
