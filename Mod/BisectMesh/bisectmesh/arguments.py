"""Checks of the arguments of the public functions: the promise of the README is that a bad
argument raises TypeError (a wrong type) or ValueError (a value that cannot be meshed), with a
message naming the Python argument, before any work starts. Nothing else leaks out (no
ZeroDivisionError from a zero count, no JSON error from a NaN that reached the core).

Also the one spacing formula of the Python side (:func:`spacing_for`) and the up-front bound on
the work a request implies (:func:`check_workload`).
"""

import math
import numbers
import os

# Volume of the regular tetrahedron of unit edge, 1/(6 sqrt 2): ``size`` and ``elements`` are
# tied by V = elements * VOLUME_PER_TET * size^3 (the thesis's nominal spacing, eq. 6.11).
VOLUME_PER_TET = 1.0 / (6.0 * math.sqrt(2.0))

# Peak memory of a meshing per tetrahedron asked for, generator and Fem.FemMesh together
# (measured in freecadcmd: 1.76 kB per tetra10 at 2e5 on a box minus a cylinder), with a
# margin: a request is refused when it would need more than half of the physical memory.
BYTES_PER_ELEMENT = 2000
_MAX_THREADS = 1024


def whole(name, value, low=None, high=None):
    """``value`` as an int: TypeError unless it is an integer (bool is not), ValueError outside
    [low, high]."""
    if isinstance(value, bool) or not isinstance(value, numbers.Integral):
        raise TypeError("%s must be a whole number, not %s (%r)" % (name, type(value).__name__, value))
    value = int(value)
    if low is not None and value < low:
        raise ValueError("%s must be at least %d (got %d)" % (name, low, value))
    if high is not None and value > high:
        raise ValueError("%s must be at most %d (got %d)" % (name, high, value))
    return value


def positive(name, value):
    """``value`` as a float > 0: TypeError unless it is a real number, ValueError when it is
    zero, negative, NaN or infinite."""
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise TypeError("%s must be a number, not %s (%r)" % (name, type(value).__name__, value))
    value = float(value)
    if not (math.isfinite(value) and value > 0):
        raise ValueError("%s must be a positive finite number (got %r)" % (name, value))
    return value


def flag(name, value):
    if not isinstance(value, bool):
        raise TypeError("%s must be True or False, not %s (%r)" % (name, type(value).__name__, value))
    return value


def optional_callable(name, value):
    if value is not None and not callable(value):
        raise TypeError("%s must be a function or None, not %s" % (name, type(value).__name__))
    return value


def optional_dict(name, value):
    if value is not None and not isinstance(value, dict):
        raise TypeError("%s must be a dict or None, not %s" % (name, type(value).__name__))
    return value


def order(value, name="order"):
    value = whole(name, value)
    if value not in (1, 2):
        raise ValueError("%s must be 1 (tetra4) or 2 (tetra10), not %d" % (name, value))
    return value


def threads(value):
    return whole("threads", value, 0, _MAX_THREADS)


def passes(name, value):
    return whole(name, value, 0, 100)


def bound(name, value):
    """A size bound in mm: a number >= 0 (0: no bound); TypeError or ValueError naming it."""
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise TypeError("%s must be a number, not %s (%r)" % (name, type(value).__name__, value))
    return 0.0 if value == 0 else positive(name, value)


def curvature_elements(value, name="curvature_elements"):
    """Elements per full circle: 0 (no bound) or 3 to 10000."""
    value = whole(name, value, 0, 10000)
    if 0 < value < 3:
        raise ValueError("%s must be 0 (no bound) or at least 3 (got %d)" % (name, value))
    return value


def count_or_size(elements, size):
    """(elements, size), exactly one of them set; ValueError naming both when neither or both."""
    if elements is not None:
        elements = whole("elements", elements, 1)
    if size is not None:
        size = positive("size", size)
    if (elements is None) == (size is None):
        raise ValueError("give elements or size (one of them), got %s" % (
            "neither" if elements is None else "both"))
    return elements, size


def part_shape_argument(shape, name="shape"):
    """A Part.Shape that is not null: TypeError for anything else."""
    if not hasattr(shape, "exportBrepToString") or not hasattr(shape, "isNull"):
        raise TypeError("%s must be a Part.Shape, not %s" % (name, type(shape).__name__))
    if shape.isNull():
        raise ValueError("%s is a null shape" % name)
    return shape


def spacing_for(volume, elements):
    """The edge length of regular tetrahedra that fill ``volume`` with ``elements`` of them."""
    return (volume / (elements * VOLUME_PER_TET)) ** (1.0 / 3.0)


def elements_for(volume, size):
    """The number of regular tetrahedra of edge ``size`` that fill ``volume``."""
    return volume / (VOLUME_PER_TET * size ** 3)


def physical_memory():
    """Bytes of physical memory, or None where the system does not say."""
    try:
        return os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES")
    except (AttributeError, ValueError, OSError):
        return None


def element_limit():
    """The tetrahedra half of the physical memory holds (BYTES_PER_ELEMENT each), 0 where the
    system does not say: the core refuses, before filling its cells, a mesh whose thin walls or
    small features would make more than that whatever ``elements`` asks."""
    memory = physical_memory()
    return 0.0 if memory is None else float(memory // 2) / BYTES_PER_ELEMENT


def check_workload(elements, volume, size, max_size=None):
    """ValueError, naming ``elements``, ``size`` or ``max_size``, when the request would take more
    than half of the physical memory (FreeCAD would be killed, or OpenCASCADE abort it, long
    before the end). The count is what ``elements`` asks, or what ``size`` fills ``volume`` with;
    ``max_size`` caps the size everywhere, so it sets a floor under the count."""
    memory = physical_memory()
    if memory is None:
        return
    limit = memory // 2
    if elements is not None:
        wanted, name, given = float(elements), "elements", "%d" % elements
    else:
        wanted, name, given = elements_for(volume, size), "size", "%g" % size
    if max_size and elements_for(volume, max_size) > wanted:
        wanted, name, given = elements_for(volume, max_size), "max_size", "%g" % max_size
    need = wanted * BYTES_PER_ELEMENT
    if need > limit:
        raise ValueError(
            "%s=%s asks for about %.3g tetrahedra, which would need about %.1f GB: more than half "
            "of this machine's memory (%.1f GB); give %s" % (
                name, given, wanted, need / 1e9, memory / 1e9,
                "fewer elements" if name == "elements" else "a larger " + name))
