"""The window never freezes, the bar tells the time, Stop stops: the mesh panel and the quality
panel at 2 * 10^5 elements in a real FreeCAD window (CTest: freecad.gui_stall; issue 19).

Run it under Xvfb from the repository root after building:

    QTWEBENGINE_CHROMIUM_FLAGS=--no-sandbox BISECTMESH_BUILD_MOD=build/Mod/BisectMesh \
    BISECTMESH_ARTIFACTS=build/test-artifacts \
    xvfb-run -a -s "-screen 0 1400x900x24" freecad tests/freecad/gui_stall.py

BISECTMESH_STALL_ELEMENTS sets the count (default 200000; the issue's other figure is 10^6).

A heartbeat (a QTimer on the GUI thread, every 10 ms) records when the event loop turns; the
longest gap between two beats is how long the window was frozen. The test meshes a filleted block
with a hole (tetra10) in the panel's worker and checks:
- the window's longest freeze while meshing, while OK hands the mesh to the document (with the 3D
  view drawing it), while the Mesh quality panel computes, and while the colouring is applied;
- the progress bar: it never goes back, and it moves in proportion to the time: at every moment
  the bar's fraction is within PROPORTIONAL of the fraction of the run's time gone;
- Stop, pressed at several moments of later runs (when the bar reaches 10, 30, 50, 70 and 90%):
  the worker has ended within STOP_WITHIN, and the panel says cancelled and keeps no mesh.
The figures go to $BISECTMESH_ARTIFACTS/gui_stall.json; the log to gui_stall.log.
"""

import json
import os
import sys
import time

import FreeCAD
import FreeCADGui
from PySide import QtCore, QtGui

HERE = os.path.dirname(os.path.abspath(globals().get("__file__", "tests/freecad/gui_stall.py")))
sys.path.insert(0, HERE)
from gui_harness import ARTIFACTS, check, dialog_button, log, select, settle, start  # noqa: E402

ELEMENTS = int(os.environ.get("BISECTMESH_STALL_ELEMENTS", "200000"))
STALL_WITHIN = float(os.environ.get("BISECTMESH_STALL_WITHIN", "0.5"))  # seconds of a frozen window, issue 19
STOP_WITHIN = float(os.environ.get("BISECTMESH_STALL_STOP", "0.5"))  # seconds from Stop to the worker's end, issue 19
PROPORTIONAL = float(os.environ.get("BISECTMESH_STALL_PROPORTIONAL", "0.2"))  # the bar's fraction against the fraction of the time gone


class Heartbeat:
    """Beats every 10 ms on the GUI thread; ``longest()`` is the longest gap since ``reset()``,
    the beat in flight included."""

    def __init__(self):
        self.timer = QtCore.QTimer()
        self.timer.setInterval(10)
        self.timer.timeout.connect(self._beat)
        self.reset()
        self.timer.start()

    def _beat(self):
        now = time.perf_counter()
        if now - self.last > self.gap:
            self.gap, self.at = now - self.last, self.last
        self.last = now

    def reset(self):
        self.last = time.perf_counter()
        self.gap, self.at = 0.0, self.last

    def longest(self):
        return max(self.gap, time.perf_counter() - self.last)


def filleted_block(doc):
    """A 100 x 60 x 40 block with a 10 mm hole, four vertical edges rounded (5 mm)."""
    import Part

    box = Part.makeBox(100, 60, 40)
    shape = box.cut(Part.makeCylinder(10, 40, FreeCAD.Vector(50, 30, 0)))
    edges = [e for e in shape.Edges if abs(e.Length - 40) < 1e-6 and e.Curve.__class__.__name__ == "Line"]
    obj = doc.addObject("Part::Feature", "FilletedBlock")
    obj.Shape = shape.makeFillet(5, edges[:4])
    doc.recompute()
    return obj


def run_until(condition, timeout, what, each=None):
    start_time = time.perf_counter()
    while not condition():
        if time.perf_counter() - start_time > timeout:
            raise AssertionError("timed out after %d s waiting for %s" % (timeout, what))
        settle(10)
        if each is not None:
            each()


def open_panel(part):
    from bisectmesh.gui import mesh_panel

    select(part)
    FreeCADGui.runCommand("BisectMesh_Mesh")
    settle(300)
    panel = mesh_panel.MeshPanel.open_panel
    check(panel is not None, "the mesh panel is open")
    panel.elements.setValue(ELEMENTS)
    panel.order.setCurrentIndex(1)
    return panel


def freecad_assign_stall(doc, femmesh, beat):
    """The window's longest freeze while a plain FEM mesh object takes ``femmesh`` and its 3D view
    draws it: what FreeCAD itself costs when any mesher's result enters the document."""
    plain = doc.addObject("Fem::FemMeshObject", "PlainFemMesh")
    settle(300)
    beat.reset()
    plain.FemMesh = femmesh
    settle(1500)
    stall = beat.longest()
    doc.removeObject(plain.Name)
    settle(300)
    return stall


def run():
    import FemGui
    import ObjectsFem
    from bisectmesh import mesh_object
    from bisectmesh.gui import quality_panel

    figures = {"elements": ELEMENTS}
    doc = FreeCAD.newDocument("GuiStall")
    analysis = ObjectsFem.makeAnalysis(doc, "Analysis")
    FemGui.setActiveAnalysis(analysis)
    part = filleted_block(doc)
    settle(300)
    beat = Heartbeat()

    # -- one meshing: the window alive, the bar's course ---------------------------------------
    panel = open_panel(part)
    course = []
    beat.reset()
    began = time.perf_counter()
    panel.mesh_button.click()
    run_until(lambda: panel.worker is None, 1800, "the meshing",
              lambda: course.append((time.perf_counter() - began, panel.progress.value() / 100.0)))
    total = time.perf_counter() - began
    figures["meshing"] = {"seconds": total, "stall": beat.longest(), "stall_at": beat.at - began}
    check(panel.error is None and panel.computed is not None, "meshed: %s" % (panel.error or panel.counts.text()))
    tets = panel.result["tets"]
    check(beat.longest() < STALL_WITHIN, "the window kept running while meshing %d tetrahedra in %.1f s "
          "(longest freeze %.2f s, at %.1f s)" % (tets, total, beat.longest(), beat.at - began))
    values = [v for _, v in course]
    check(values == sorted(values), "the bar never went back")
    off = max(abs(v - t / total) for t, v in course)
    worst = max(course, key=lambda c: abs(c[1] - c[0] / total))
    figures["bar"] = {"samples": len(course), "largest_offset": off,
                      "course": [(round(t / total, 3), v) for t, v in course[::max(1, len(course) // 50)]]}
    check(off <= PROPORTIONAL, "the bar followed the time: largest offset %.2f (at %.0f%% of the time it "
          "showed %.0f%%)" % (off, 100 * worst[0] / total, 100 * worst[1]))

    # -- OK: the mesh into the document and the 3D view ----------------------------------------
    # FreeCAD's own part of OK, the same for any mesher's result: copying the FemMesh into the
    # object's property and building its 3D view, both on the GUI thread. Measured with a plain
    # FEM mesh object taking the same mesh, once before OK and once after, the larger kept: on a
    # shared machine one such measurement alone varies by more than STALL_WITHIN (CI saw 1.48 s
    # where this machine saw 1.99 s). OK may add at most STALL_WITHIN to it.
    femmesh = panel.computed[1]
    references = [freecad_assign_stall(doc, femmesh, beat)]
    beat.reset()
    dialog_button(QtGui.QDialogButtonBox.Ok).click()
    settle(1500)
    figures["ok_stall"] = beat.longest()
    objs = [o for o in doc.Objects if mesh_object.is_mesh_object(o)]
    check(len(objs) == 1 and objs[0].FemMesh.VolumeCount == tets, "OK kept the mesh")
    obj = objs[0]
    references.append(freecad_assign_stall(doc, femmesh, beat))
    figures["freecad_assign_stalls"] = references
    figures["freecad_assign_stall"] = max(references)
    check(figures["ok_stall"] < figures["freecad_assign_stall"] + STALL_WITHIN,
          "OK froze the window for %.2f s, of which FreeCAD's own copy of the mesh into a FEM mesh object and "
          "its 3D view take %.2f s (measured %s)" % (figures["ok_stall"], figures["freecad_assign_stall"],
                                                     ", ".join("%.2f s" % r for r in references)))

    # -- the quality panel and its colouring ---------------------------------------------------
    select(obj)
    beat.reset()
    FreeCADGui.runCommand("BisectMesh_Quality")
    run_until(lambda: quality_panel.QualityPanel.open_panel is not None
              and quality_panel.QualityPanel.open_panel.report is not None, 600, "the quality report")
    settle(300)
    figures["quality_stall"] = beat.longest()
    qpanel = quality_panel.QualityPanel.open_panel
    check(qpanel.report["tets"] == tets and qpanel.report["valid"], "the quality panel reports the mesh valid")
    check(figures["quality_stall"] < STALL_WITHIN, "Mesh quality froze the window for at most %.2f s"
          % figures["quality_stall"])
    beat.reset()
    qpanel.colour.setChecked(True)
    run_until(qpanel.colouring_done, 600, "the colouring")
    settle(1000)
    figures["colour_stall"] = beat.longest()
    check(figures["colour_stall"] < STALL_WITHIN, "Colour by quality froze the window for at most %.2f s"
          % figures["colour_stall"])
    FreeCADGui.Control.closeDialog()
    settle(300)

    # -- Stop at moments spread over later runs ------------------------------------------------
    figures["stops"] = []
    panel = open_panel(part)
    for k in range(5):
        # the moment by the bar (which follows the time, checked above), not by the first run's
        # clock: a later run can be much faster than the first, which pays for the first use of
        # OpenCASCADE and the module (CI saw 5.2 s, then 3.3 s and 3.7 s), and moments at 70% and
        # 90% of the first run's time came after the later runs had ended
        share = (k + 0.5) / 5
        panel.mesh_button.click()
        run_until(lambda: panel.progress.value() / 100.0 >= share or panel.worker is None, 1800, "the moment to stop")
        if panel.worker is None:
            continue  # it finished first
        beat.reset()
        pressed = time.perf_counter()
        panel.stop_button.click()
        run_until(lambda: panel.worker is None, 60, "the worker to stop")
        latency = time.perf_counter() - pressed
        figures["stops"].append({"at": share, "latency": latency, "stall": beat.longest()})
        check("cancelled" in panel.status.text() and panel.computed is None,
              "Stop at %.0f%% of the bar: cancelled after %.2f s, no mesh kept" % (100 * share, latency))
        check(latency < STOP_WITHIN, "Stop took effect within %.1f s" % STOP_WITHIN)
    check(len(figures["stops"]) >= 4, "stopped at %d moments" % len(figures["stops"]))
    dialog_button(QtGui.QDialogButtonBox.Cancel).click()
    settle(300)
    with open(os.path.join(ARTIFACTS, "gui_stall.json"), "w") as f:
        json.dump(figures, f, indent=1)
    log("figures: " + json.dumps({k: v for k, v in figures.items() if k != "bar"}))
    FreeCAD.closeDocument(doc.Name)


start("gui_stall", run)
