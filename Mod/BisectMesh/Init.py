# BisectMesh: run by FreeCAD (GUI or not) when it starts. FreeCAD has put this folder on
# sys.path by now, so `import bisectmesh` works in macros and in freecadcmd scripts.
#
# Nothing is imported here on purpose: the package and its compiled core load when first used,
# which keeps FreeCAD's start-up untouched by BisectMesh.
