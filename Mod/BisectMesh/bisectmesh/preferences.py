"""BisectMesh's defaults, as the preferences page (Edit > Preferences > BisectMesh) stores them in
``User parameter:BaseApp/Preferences/Mod/BisectMesh``.

:func:`defaults` reads them, falling back to the built-in value for a key that is unset or holds
a value the mesher would refuse (a user.cfg edited by hand must not break the commands). The new
mesh objects (:func:`bisectmesh.make_mesh_object`) and the task panel start from them; a mesh
object keeps its own values once made.

No GUI here: freecadcmd and macros read the same defaults.
"""

PATH = "User parameter:BaseApp/Preferences/Mod/BisectMesh"

# The built-in defaults: (parameter type, key, value)
DEFAULT_ELEMENTS = 5000
BUILT_IN = (
    ("Bool", "UseElementSize", False),  # False: the count (DefaultElements), True: DefaultSize
    ("Int", "DefaultElements", DEFAULT_ELEMENTS),
    ("Float", "DefaultSize", 1.0),  # mm
    ("Int", "DefaultOrder", 2),
    ("Int", "CurvatureElements", 12),  # elements per full circle (0: no bound)
    ("Int", "Threads", 0),  # 0: one per core
    ("Int", "OptimizePasses", 3),
    ("Int", "SmoothPasses", 3),
)

# What the mesher accepts for each key; anything else falls back to the built-in value.
_ACCEPT = {
    "DefaultElements": lambda v: v >= 1,
    "DefaultSize": lambda v: v > 0 and v < 1e12,
    "DefaultOrder": lambda v: v in (1, 2),
    "CurvatureElements": lambda v: v == 0 or 3 <= v <= 10000,
    "Threads": lambda v: 0 <= v <= 1024,
    "OptimizePasses": lambda v: 0 <= v <= 100,
    "SmoothPasses": lambda v: 0 <= v <= 100,
}


def _group():
    import FreeCAD

    return FreeCAD.ParamGet(PATH)


def read(key):
    """The stored value of one key of BUILT_IN, or its built-in value."""
    for kind, name, value in BUILT_IN:
        if name == key:
            stored = getattr(_group(), "Get" + kind)(name, value)
            accept = _ACCEPT.get(name)
            return stored if accept is None or accept(stored) else value
    raise KeyError("no BisectMesh preference %r (%s)" % (key, ", ".join(n for _, n, _ in BUILT_IN)))


def defaults():
    """{key: value} for every key of BUILT_IN."""
    return {name: read(name) for _, name, _ in BUILT_IN}


def write(values):
    """Stores {key: value} (keys of BUILT_IN); what the preferences page's saveSettings does."""
    group = _group()
    kinds = {name: kind for kind, name, _ in BUILT_IN}
    for name, value in values.items():
        if name not in kinds:
            raise KeyError("no BisectMesh preference %r" % name)
        getattr(group, "Set" + kinds[name])(name, value)


def count_or_size():
    """(elements, size) of the defaults: one of them None."""
    if read("UseElementSize"):
        return None, float(read("DefaultSize"))
    return int(read("DefaultElements")), None
