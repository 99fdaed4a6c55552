"""FreeCAD's own FEM examples (``femexamples``) re-meshed by BisectMesh and solved in CalculiX.

For every example of FreeCAD 0.20.2's ``femexamples`` that is a static (or thermomechanical)
CalculiX analysis on solid elements (EXAMPLES below), one test:

1. sets the example up (``setup(doc, "ccxtools")``), solves it with the shipped mesh through
   FreeCAD's ccxtools and records the largest displacement magnitude of the result;
2. sets it up again, re-meshes the solid geometry (the mesh object's Part, else the one object the
   constraints reference) with ``bisectmesh.shape_mesher.mesh_shape(shape, elements=N, order=2)``,
   N being the shipped mesh's tetrahedron count (for a hexahedral mesh 6 tetrahedra per hexahedron,
   the split of a hexahedron into tetrahedra on its own corners), puts the mesh into the analysis'
   mesh object (``obj.FemMesh = mesh``: the constraints reference geometry, and FreeCAD's writer
   finds their nodes and elements by geometry), solves and records;
3. does the same with FreeCAD's own Gmsh mesher (femmesh.gmshtools, the example's mesh object,
   2nd order, CharacteristicLengthMin 0), CharacteristicLengthMax searched a few times for a
   tetrahedron count within 20 % of N (the count closest to N is kept). Gmsh 4.8 does not go below
   some 200 tetrahedra on a box, some 1150 on the 10 mm cube of boxanalysis_static, some 1450 on
   the two boxes of material_multiple_tensionrod_twoboxes, whatever the length: there its mesh is
   finer than N (the JSON says so: count_within_tolerance), and the comparison is kept, the
   stricter choice.

It asserts that BisectMesh's mesh solves (ccx exits cleanly, writes no *ERROR and no nonpositive
Jacobian, and a result is loaded), and, wherever Gmsh's largest displacement is within 1 % of the
shipped mesh's, that BisectMesh's is within 2 % of it. Where Gmsh is not within 1 % (the shipped
mesh is far from converged, or of another element type), and for the examples of SOLVE_ONLY, whose
largest displacement is ill-defined, only the solve is asserted; the figures are still written.

The largest displacement is the maximum over the nodes of |u| in the last result ccx writes (for
the nonlinear material the end of the load). Figures (counts, displacements, errors, seconds) go to
$BISECTMESH_ARTIFACTS/femexamples.json.

Examples run (see EXAMPLES):
    boxanalysis_static, ccx_cantilever_ele_hexa20, ccx_cantilever_ele_tetra4,
    ccx_cantilever_faceload, ccx_cantilever_nodeload, ccx_cantilever_prescribeddisplacement,
    constraint_contact_solid_solid, constraint_section_print, constraint_selfweight_cantilever,
    constraint_tie, constraint_transform_beam_hinged, constraint_transform_torque,
    material_multiple_bendingbeam_fiveboxes, material_multiple_tensionrod_twoboxes,
    thermomech_bimetall, thermomech_spine

Solved but not compared (see SOLVE_ONLY):
    constraint_transform_beam_hinged: singular (the beam may slide along its pins), the largest
    displacement holds an arbitrary rigid drift and varies between runs of the same mesh

Known BisectMesh failures, marked expectedFailure (see KNOWN_MESHER_FAILURES): none since cells
that no point sees whole are filled by Delaunay boundary recovery (constraint_contact_solid_solid
and constraint_transform_torque failed with a MeshingError at the shipped count before).

Left out, with the reason (see LEFT_OUT): the shell, beam and 2D examples, the frequency and
buckling analyses, the Elmer-only examples, constraint_centrif (its fixed faces hold only one of
its two rings in FreeCAD 0.20.2, the system is singular), material_nl_platewithhole (too slow for
this test: three elasto-plastic ccx runs of about 23 s each; BISECTMESH_FEMEXAMPLES_SLOW=1 runs
it too).

The ccx_cantilever_ele_tetra4 example ships no mesh: its reference is Gmsh's tetra4 mesh at the
example's own settings; being tetra4 it is far from the tetra10 results (some 7 %), so there only
the solve is asserted.
"""

import json
import math
import os
import shutil
import tempfile
import time
import unittest

import FreeCAD

from fc_helpers import artifacts_dir
from test_cantilever import _remove_gmsh_temp_dir, _which_ccx, _which_gmsh

# The examples compared: name -> what it is (static CalculiX analyses of solid elements).
EXAMPLES = {
    "boxanalysis_static": "box, fixed face, force and pressure; tetra10",
    "ccx_cantilever_ele_hexa20": "cantilever 8000 x 1000 x 1000, face load; hexa20 (N = 6 per hexahedron)",
    "ccx_cantilever_ele_tetra4": "cantilever, face load; its mesh is Gmsh's at the example's own "
                                 "settings (1st order, 150 mm), not shipped: that tetra4 mesh is the reference",
    "ccx_cantilever_faceload": "cantilever, face load; tetra10",
    "ccx_cantilever_nodeload": "cantilever, loads on the end face's four vertices; tetra10",
    "ccx_cantilever_prescribeddisplacement": "cantilever, prescribed end-face displacement; tetra10",
    "constraint_contact_solid_solid": "box and half cylinder in contact (penalty contact); tetra10",
    "constraint_section_print": "two solids (BooleanFragments), pressure, section print; tetra10",
    "constraint_selfweight_cantilever": "cantilever under self weight; tetra10",
    "constraint_tie": "a 359-degree conical shell, the faces of its gap tied, edge-fixed, edge load; tetra10",
    "constraint_transform_beam_hinged": "hinged beam, transformed displacement constraints; tetra10",
    "constraint_transform_torque": "tube, torque through a cylindrical transform; tetra10",
    "material_multiple_bendingbeam_fiveboxes": "five boxes (CompSolid), three materials; tetra10",
    "material_multiple_tensionrod_twoboxes": "two boxes (CompSolid), two materials; tetra10",
    "thermomech_bimetall": "bimetal strip, steady thermomechanical, two materials; tetra10",
    "thermomech_spine": "thermomechanical box with heat flux (12 tetra10 shipped); tetra10",
}

# Examples where BisectMesh itself fails: the test is marked expectedFailure, so that it turns
# into an unexpected success (a failing run) once fixed. None at present.
KNOWN_MESHER_FAILURES = {}

# Examples solved (BisectMesh's mesh must solve) whose largest displacement is not compared, with
# the reason.
SOLVE_ONLY = {
    "constraint_transform_beam_hinged": (
        "singular: the displacement constraint fixes only the radial direction (cylindrical transform) "
        "of the two pin holes, whose axes are parallel to y, so the beam is free to slide along y; "
        "SPOOLES returns an arbitrary rigid y-drift (-0.24 mm in the shipped run, the beam's bending "
        "about 1 mm) that varies between runs of the very same mesh: the largest |u| of the shipped "
        "mesh came out 1.0168 and 1.0202 mm, Gmsh's from 0.99 to 1.43 mm at 1100 to 1400 tetrahedra. "
        "No measure of the mesh"),
}

# Examples of femexamples not compared, with the reason.
LEFT_OUT = {
    "boxanalysis_frequency": "frequency analysis: eigenmodes, no static displacement to compare",
    "frequency_beamsimple": "frequency analysis: eigenmodes, no static displacement to compare",
    "elmer_nonguitutorial01_eigenvalue_of_elastic_beam": "eigenvalue (frequency) analysis",
    "ccx_buckling_flexuralbuckling": "buckling analysis (buckling factors, normalised modes); hexa8",
    "buckling_lateraltorsionalbuckling": "buckling analysis of a shell (face) mesh",
    "buckling_platebuckling": "buckling analysis of a shell (face) mesh",
    "ccx_cantilever_beam_circle": "beam (edge) elements",
    "ccx_cantilever_beam_pipe": "beam (edge) elements",
    "ccx_cantilever_beam_rect": "beam (edge) elements",
    "ccx_cantilever_ele_seg2": "beam (edge) elements",
    "ccx_cantilever_ele_seg3": "beam (edge) elements",
    "truss_3d_cs_circle_ele_seg2": "truss (edge) elements, Z88 only",
    "truss_3d_cs_circle_ele_seg3": "truss (edge) elements",
    "thermomech_flow1d": "1D fluid (edge) elements",
    "ccx_cantilever_ele_quad4": "shell (face) elements",
    "ccx_cantilever_ele_quad8": "shell (face) elements",
    "ccx_cantilever_ele_tria3": "shell (face) elements",
    "ccx_cantilever_ele_tria6": "shell (face) elements",
    "constraint_contact_shell_shell": "shell (face) elements",
    "material_multiple_bendingbeam_fivefaces": "shell (face) elements",
    "mystran_plate": "shell (face) elements",
    "rc_wall_2d": "2D (plane stress, face) elements",
    "square_pipe_end_twisted_edgeforces": "shell (face) elements",
    "square_pipe_end_twisted_nodeforces": "shell (face) elements",
    "equation_electrostatics_capacitance_two_balls": "Elmer electrostatics, no CalculiX analysis",
    "equation_electrostatics_electricforce_elmer_nongui6": "Elmer electrostatics, no CalculiX analysis",
    "constraint_centrif": (
        "ill-posed in FreeCAD 0.20.2: the fixed constraint's Face4 and Face12 of the compound both "
        "lie on the lower ring, the upper ring is free; ccx's largest displacement is 9.5e6 mm with "
        "the shipped (tetra4) mesh, nothing to compare"),
}

# Compared only when BISECTMESH_FEMEXAMPLES_SLOW=1 is set, else left out for the time they take.
SLOW = {
    "material_nl_platewithhole": (
        "plate with a hole, elasto-plastic material (nonlinear, the result at the end of the load); "
        "tetra10; each ccx run of its 6524 tetrahedra takes about 23 s on two cores, the example 77 s. "
        "Measured: shipped 1.65816 mm; Gmsh 6968 tetrahedra 1.65175 mm (0.39 %); BisectMesh 6794 "
        "tetrahedra 1.66346 mm (0.32 %)"),
}
if os.environ.get("BISECTMESH_FEMEXAMPLES_SLOW", "").strip() not in ("", "0"):
    EXAMPLES.update(SLOW)
else:
    LEFT_OUT.update({name: "too slow for a CI run (set BISECTMESH_FEMEXAMPLES_SLOW=1 to run it): "
                     + reason for name, reason in SLOW.items()})

GMSH_COUNT_TOLERANCE = 0.20  # Gmsh's tetrahedron count sought within 20 % of N
GMSH_TRIES = 5  # CharacteristicLengthMax values tried at most
GMSH_BOUND = 0.01  # where Gmsh is within 1 % of the shipped mesh ...
BISECT_BOUND = 0.02  # ... BisectMesh must be within 2 %
HEXA_TETRAHEDRA = 6  # tetrahedra per hexahedron for the count of a hexahedral shipped mesh

FIGURES = {}  # example -> figures, written to femexamples.json
FIGURES_TOTAL = {}  # the whole run: seconds


def _analysis(doc):
    analyses = [o for o in doc.Objects if o.isDerivedFrom("Fem::FemAnalysis")]
    if len(analyses) != 1:
        raise RuntimeError("%d analyses in the example" % len(analyses))
    return analyses[0]


def _member(analysis, test):
    found = [o for o in analysis.Group if test(o)]
    if len(found) != 1:
        raise RuntimeError("%d matching members in %s" % (len(found), analysis.Name))
    return found[0]


def _mesh_object(analysis):
    return _member(analysis, lambda o: o.isDerivedFrom("Fem::FemMeshObject"))


def _solver(analysis):
    return _member(analysis, lambda o: o.isDerivedFrom("Fem::FemSolverObjectPython"))


def _volume_kind(femmesh):
    """Nodes per volume element (4, 10, 8, 20) of the first volume, None without volumes."""
    for vid in femmesh.Volumes:
        return len(femmesh.getElementNodes(vid))
    return None


def _solid_shape(doc, analysis, mesh_obj):
    """The geometry to re-mesh: the mesh object's Part, else the one object the constraints
    reference."""
    part = getattr(mesh_obj, "Part", None)
    if part is not None:
        return part.Shape
    objects = {ref[0].Name: ref[0] for o in analysis.Group for ref in getattr(o, "References", [])
               if o.isDerivedFrom("Fem::Constraint")}
    if len(objects) != 1:
        raise RuntimeError("no Part and the constraints reference %s" % sorted(objects))
    return list(objects.values())[0].Shape


def _setup(name):
    import importlib

    module = importlib.import_module("femexamples." + name)
    doc = FreeCAD.newDocument(name.replace(".", "_"))
    module.setup(doc, "ccxtools")
    doc.recompute()
    analysis = _analysis(doc)
    return doc, analysis, _mesh_object(analysis), _solver(analysis)


def _solve(analysis, solver, mesh_obj, work_dir):
    """Writes the input file, runs ccx, loads the results; returns (largest |u|, seconds of the
    writer, seconds of ccx, number of result objects). Raises RuntimeError on any ccx trouble."""
    from femtools import ccxtools

    fea = ccxtools.FemToolsCcx(analysis, solver)
    fea.update_objects()
    os.makedirs(work_dir, exist_ok=True)
    fea.setup_working_dir(work_dir)
    if os.path.abspath(fea.working_dir) != os.path.abspath(work_dir):
        raise RuntimeError("ccxtools chose the working directory %s over %s" % (fea.working_dir, work_dir))
    fea.setup_ccx()
    message = fea.check_prerequisites()
    if message:
        raise RuntimeError("CalculiX prerequisites: %s" % message)
    start = time.perf_counter()
    fea.write_inp_file()
    write_seconds = time.perf_counter() - start
    if not fea.inp_file_name:
        raise RuntimeError("the CalculiX input file was not written")
    start = time.perf_counter()
    code = fea.ccx_run()
    ccx_seconds = time.perf_counter() - start
    stdout = fea.ccx_stdout or ""
    if "nonpositive jacobian" in stdout:
        bad = sorted({int(line.split()[3]) for line in stdout.splitlines() if "determinant in element" in line})
        raise RuntimeError("ccx: nonpositive Jacobian in %d elements %s" % (len(bad), bad[:20]))
    if code or "*ERROR" in stdout:
        raise RuntimeError("ccx failed (exit code %s): %s\n%s" % (code, fea.ccx_stderr, stdout[-2000:]))
    fea.load_results()
    results = [m for m in analysis.Group if m.isDerivedFrom("Fem::FemResultObject")]
    if not results:
        raise RuntimeError("no result object after loading the CalculiX results")
    lengths = results[-1].DisplacementLengths
    if not lengths:
        raise RuntimeError("the result %s holds no displacement" % results[-1].Name)
    largest = max(lengths)
    if not math.isfinite(largest):
        raise RuntimeError("the largest displacement is %r" % largest)
    return largest, write_seconds, ccx_seconds, len(results)


def _mesh_figures(femmesh):
    return {"tetrahedra": femmesh.VolumeCount if _volume_kind(femmesh) in (4, 10) else 0,
            "volumes": femmesh.VolumeCount, "nodes": femmesh.NodeCount,
            "nodes_per_element": _volume_kind(femmesh)}


def _gmsh(mesh_obj, length, order):
    """Meshes the mesh object's Part with Gmsh at CharacteristicLengthMax ``length`` (mm)."""
    from femmesh.gmshtools import GmshTools

    mesh_obj.ElementOrder = "2nd" if order == 2 else "1st"
    mesh_obj.CharacteristicLengthMax = "%.9g mm" % length
    mesh_obj.CharacteristicLengthMin = "0 mm"
    mesh_obj.Document.recompute()
    tools = GmshTools(mesh_obj)
    try:
        error = tools.create_mesh()
    finally:
        _remove_gmsh_temp_dir(tools)
    if error:
        raise RuntimeError("Gmsh failed at %g mm: %s" % (length, error))
    mesh_obj.Document.recompute()
    return mesh_obj.FemMesh.VolumeCount


def _gmsh_at_count(mesh_obj, target, volume):
    """Gmsh (2nd order) at a tetrahedron count within GMSH_COUNT_TOLERANCE of ``target``: starts from
    the edge of a regular tetrahedron of volume / target and scales the length by the cube root of
    count / target (at most by 2), GMSH_TRIES times at most. A length where Gmsh fails (it reports
    inverted elements, say) is recorded and the next tried 10 % smaller; the search stops early when
    a longer length gives no fewer tetrahedra (Gmsh's floor: a box gets some 200 tetrahedra however
    long the length). Leaves the mesh of the count closest to the target in ``mesh_obj``; returns the
    tries [(length, count or None, Gmsh's message or None)] and the length kept."""
    length = (6.0 * math.sqrt(2.0) * volume / target) ** (1.0 / 3.0)
    tries = []
    for _ in range(GMSH_TRIES):
        try:
            count = _gmsh(mesh_obj, length, 2)
        except RuntimeError as e:
            tries.append((length, None, str(e)[:500]))
            length *= 0.9
            continue
        meshed = [t for t in tries if t[1]]
        tries.append((length, count, None))
        if abs(count - target) <= GMSH_COUNT_TOLERANCE * target:
            break
        if meshed and length > meshed[-1][0] and count >= meshed[-1][1]:
            break  # Gmsh's floor: no coarser mesh to be had
        length *= min(2.0, max(0.5, (count / target) ** (1.0 / 3.0)))
    meshed = [t for t in tries if t[1]]
    if not meshed:
        raise RuntimeError("Gmsh failed at every length tried: %s" % tries)
    best = min(meshed, key=lambda t: abs(math.log(t[1] / target)))
    if best is not tries[-1]:
        _gmsh(mesh_obj, best[0], 2)
    return tries, best[0]


def relative_error(value, reference):
    return abs(value - reference) / abs(reference)


def run_example(name, work_dir):
    """Shipped mesh, Gmsh and BisectMesh on example ``name``; fills FIGURES[name] as it goes (so
    that a failure keeps what was measured) and returns it. BisectMesh's exception is re-raised
    after the other two have run."""
    from bisectmesh import shape_mesher

    figures = FIGURES.setdefault(name, {"description": EXAMPLES[name]})
    start_all = time.perf_counter()

    # 1. the shipped mesh (for ccx_cantilever_ele_tetra4: Gmsh at the example's own settings)
    doc, analysis, mesh_obj, solver = _setup(name)
    try:
        start = time.perf_counter()
        if mesh_obj.FemMesh.VolumeCount == 0:
            from femmesh.gmshtools import GmshTools

            tools = GmshTools(mesh_obj)
            try:
                error = tools.create_mesh()
            finally:
                _remove_gmsh_temp_dir(tools)
            if error:
                raise RuntimeError("Gmsh failed on the example's own mesh settings: %s" % error)
            doc.recompute()
            figures["shipped_mesh"] = "Gmsh at the example's own settings (ElementOrder %s, " \
                "CharacteristicLengthMax %s)" % (mesh_obj.ElementOrder, mesh_obj.CharacteristicLengthMax)
        shipped = _mesh_figures(mesh_obj.FemMesh)
        shipped["mesh_seconds"] = time.perf_counter() - start
        shape = _solid_shape(doc, analysis, mesh_obj)
        volume = shape.Volume
        figures["solids"] = len(shape.Solids)
        figures["shape_volume"] = volume
        figures["analysis_type"] = solver.AnalysisType
        shipped["displacement"], shipped["write_seconds"], shipped["ccx_seconds"], shipped["results"] = _solve(
            analysis, solver, mesh_obj, os.path.join(work_dir, name, "shipped"))
        figures["shipped"] = shipped
    finally:
        FreeCAD.closeDocument(doc.Name)
    kind = shipped["nodes_per_element"]
    target = shipped["volumes"] * (HEXA_TETRAHEDRA if kind in (8, 20) else 1)
    figures["elements_asked"] = target
    reference = shipped["displacement"]

    # 2. FreeCAD's Gmsh mesher at a comparable count
    doc, analysis, mesh_obj, solver = _setup(name)
    try:
        start = time.perf_counter()
        tries, length = _gmsh_at_count(mesh_obj, target, volume)
        gmsh = _mesh_figures(mesh_obj.FemMesh)
        gmsh.update(mesh_seconds=time.perf_counter() - start, tries=tries, characteristic_length_max=length,
                    count_within_tolerance=abs(gmsh["tetrahedra"] - target) <= GMSH_COUNT_TOLERANCE * target)
        figures["gmsh"] = gmsh
        gmsh["displacement"], gmsh["write_seconds"], gmsh["ccx_seconds"], gmsh["results"] = _solve(
            analysis, solver, mesh_obj, os.path.join(work_dir, name, "gmsh"))
        gmsh["error"] = relative_error(gmsh["displacement"], reference)
    except Exception as e:  # Gmsh's trouble is no BisectMesh failure: recorded, the comparison left out
        figures.setdefault("gmsh", {})["failure"] = "%s: %s" % (type(e).__name__, e)
    finally:
        FreeCAD.closeDocument(doc.Name)

    # 3. BisectMesh at N
    doc, analysis, mesh_obj, solver = _setup(name)
    bisect = figures["bisectmesh"] = {}
    try:
        start = time.perf_counter()
        try:
            report = {}
            femmesh = shape_mesher.mesh_shape(_solid_shape(doc, analysis, mesh_obj), elements=target, order=2,
                                              report=report)
        except Exception as e:
            bisect["failure"] = "mesh_shape(elements=%d, order=2): %s: %s" % (target, type(e).__name__, e)
            raise
        bisect.update(_mesh_figures(femmesh))
        bisect["mesh_seconds"] = time.perf_counter() - start
        bisect["mesher_seconds"] = report.get("seconds")
        mesh_obj.FemMesh = femmesh
        doc.recompute()
        try:
            bisect["displacement"], bisect["write_seconds"], bisect["ccx_seconds"], bisect["results"] = _solve(
                analysis, solver, mesh_obj, os.path.join(work_dir, name, "bisectmesh"))
        except Exception as e:
            bisect["failure"] = "solve: %s: %s" % (type(e).__name__, e)
            raise
        bisect["error"] = relative_error(bisect["displacement"], reference)
    finally:
        FreeCAD.closeDocument(doc.Name)
        figures["seconds"] = time.perf_counter() - start_all
    return figures


def _write_json():
    path = os.path.join(artifacts_dir(), "femexamples.json")
    with open(path, "w") as f:
        json.dump({"examples": FIGURES, "left_out": LEFT_OUT, "known_mesher_failures": KNOWN_MESHER_FAILURES,
                   "solve_only": SOLVE_ONLY,
                   "bounds": {"gmsh": GMSH_BOUND, "bisectmesh": BISECT_BOUND,
                              "gmsh_count_tolerance": GMSH_COUNT_TOLERANCE},
                   "freecad": ".".join(FreeCAD.Version()[:3]), "total": FIGURES_TOTAL}, f, indent=2, sort_keys=True)
    return path


def _summary_line(name, figures):
    def part(key):
        case = figures.get(key, {})
        if "displacement" not in case:
            return "%s -" % key
        error = case.get("error")
        return "%s %.6g (%d, %s)" % (key, case["displacement"], case.get("tetrahedra", 0),
                                     "-" if error is None else "%.3f %%" % (100 * error))
    return "%s: %s, %s, %s, %.1f s" % (name, part("shipped"), part("gmsh"), part("bisectmesh"),
                                       figures.get("seconds", 0.0))


@unittest.skipIf(_which_ccx() is None, "CalculiX (ccx) is not installed")
@unittest.skipIf(_which_gmsh() is None, "Gmsh is not installed")
class FemExamplesTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.work_dir = tempfile.mkdtemp(prefix="bisectmesh-femexamples-")
        cls.start = time.perf_counter()

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.work_dir, ignore_errors=True)
        FIGURES_TOTAL["seconds"] = time.perf_counter() - cls.start
        path = _write_json()
        print("\nfemexamples (largest displacement, tetrahedra, error against the shipped mesh):")
        for name in sorted(FIGURES):
            print("  " + _summary_line(name, FIGURES[name]))
        print("  %.1f s; %s" % (FIGURES_TOTAL["seconds"], path))

    def check_example(self, name):
        try:
            figures = run_example(name, self.work_dir)
        except Exception:
            failure = FIGURES.get(name, {}).get("bisectmesh", {}).get("failure")
            if failure:
                print("\n%s: BisectMesh: %s" % (name, failure))
            raise
        finally:
            _write_json()
        bisect, gmsh = figures["bisectmesh"], figures.get("gmsh", {})
        self.assertEqual(bisect["nodes_per_element"], 10, name)
        self.assertGreater(bisect["displacement"], 0.0, name)
        figures["compared"] = (name not in SOLVE_ONLY and gmsh.get("error") is not None
                               and gmsh["error"] <= GMSH_BOUND)
        if name in SOLVE_ONLY:
            figures["not_compared"] = SOLVE_ONLY[name]
        _write_json()
        if figures["compared"]:
            self.assertLessEqual(bisect["error"], BISECT_BOUND, "%s: %s" % (name, _summary_line(name, figures)))


def _make_test(name):
    def test(self):
        self.check_example(name)
    test.__name__ = "test_" + name
    test.__doc__ = EXAMPLES[name]
    if name in KNOWN_MESHER_FAILURES:
        test = unittest.expectedFailure(test)
    return test


for _name in EXAMPLES:
    setattr(FemExamplesTest, "test_" + _name, _make_test(_name))
del _name


if __name__ == "__main__":
    unittest.main()
