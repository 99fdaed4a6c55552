"""The FreeCAD GUI side of BisectMesh: commands and task panels.

Only the modules that draw widgets need FreeCADGui and Qt; :mod:`.colouring` and
:mod:`.histograms` compute what they show and import without a GUI.
"""

import os

_PACKAGE_DIR = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def icon_path(name):
    """Full path of an icon of ours, e.g. ``icon_path("BisectMesh_Quality.svg")``.

    Installed (and staged in the build tree) the icons sit in ``Mod/BisectMesh/icons``; in the
    source tree they are in the repository's top-level ``icons`` folder."""
    mod_dir = os.path.dirname(_PACKAGE_DIR)
    for folder in (os.path.join(mod_dir, "icons"),
                   os.path.join(mod_dir, os.pardir, os.pardir, "icons")):
        candidate = os.path.normpath(os.path.join(folder, name))
        if os.path.isfile(candidate):
            return candidate
    return ""
