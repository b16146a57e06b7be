# RmfSurf addon, application part: FreeCAD runs this file at start-up (also in freecadcmd),
# with this folder on sys.path, so that `import rmfsurf_workbench` (the features and their
# make_* functions) and `import rmfsurf` (the library, installed into this folder by
# scripts/install-freecad-addon) work in scripts and in documents that hold the features.
# Nothing is loaded until a feature is made or a document with one is opened.
