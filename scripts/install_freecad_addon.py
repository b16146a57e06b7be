"""The FreeCAD side of scripts/install-freecad-addon, run by `freecadcmd` so that every
question is answered by the FreeCAD that will load the addon: its user directory (for the
$HOME it runs with), its Python and platform.

Environment (set by the shell script):
  RMFSURF_ADDON_SOURCE  the addon folder (freecad/ of the repository)
  RMFSURF_WHEEL         the wheel of the Python package rmfsurf (it carries librmfsurf)
  RMFSURF_ADDON_INTO    where to write the addon tree; empty: <user data>/Mod/RmfSurf
  RMFSURF_ADDON_CHECK   "1": do not install; check that the installed addon loads
  RMFSURF_LICENSES      the folder of the license files (the repository's root)
  RMFSURF_CFFI_WHEELS   a folder of cffi wheels, one per CPython version

The addon tree is the addon folder with the wheel unpacked into it (rmfsurf/ and its
dist-info), the license files package.xml names, and cffi's compiled backend
(_cffi_backend.cpython-3X-*.so, one per CPython version, each Python loading its own):
FreeCAD puts the addon's folder on sys.path when it starts, so the workbench, documents
holding its features and the user's scripts all find `rmfsurf` there — one folder to
install, update or delete, the library always the version the workbench was released
with. freecadcmd exits 0 even when a script raises, so this one exits 1 itself.
"""

import os
import platform
import shutil
import sys
import sysconfig
import traceback
import xml.etree.ElementTree as ElementTree
import zipfile

import FreeCAD

ADDON_NAME = "RmfSurf"
PREFIX = "install-freecad-addon: "


def say(text):
    # FreeCAD's banner and progress output share stdout; the shell script keeps our lines.
    print("\n" + PREFIX + text)


class Refused(Exception):
    pass


def manifest(folder):
    """A function giving the elements of a tag directly under the <package> of the
    package.xml in `folder` (qualified with the file's namespace), or None when there is no
    package.xml."""
    path = os.path.join(folder, "package.xml")
    if not os.path.isfile(path):
        return None
    root = ElementTree.parse(path).getroot()
    namespace = root.tag[:root.tag.index("}") + 1] if root.tag.startswith("{") else ""
    return lambda tag: root.findall(namespace + tag)


def package_name(folder):
    """The <name> of the package.xml in `folder`, or None."""
    children = manifest(folder)
    names = children("name") if children else []
    return names[0].text.strip() if names else None


def wheel_platform(wheel):
    """The platform tag of a wheel file name (name-version-python-abi-platform.whl)."""
    return os.path.basename(wheel)[:-len(".whl")].split("-")[-1]


def check_platform(wheel):
    """Refuses a wheel whose library cannot load in this FreeCAD (another OS or machine)."""
    tag = wheel_platform(wheel)
    here = sysconfig.get_platform().replace("-", "_").replace(".", "_")
    machine = platform.machine()
    compatible = tag == "any" or tag == here or (
        here.startswith("linux_") and tag.startswith(("manylinux", "musllinux"))
        and tag.endswith("_" + machine))
    if not compatible:
        raise Refused("the wheel %s is built for %s, this FreeCAD runs on %s"
                      % (os.path.basename(wheel), tag, here))


def bundled_backend_fits(wheels):
    """Whether one of the cffi wheels to bundle is for this Python (cpXY)."""
    tag = "-cp%d%d-" % sys.version_info[:2]
    return any(tag in name for name in os.listdir(wheels))


def check_python_modules(wheels):
    """The package's run-time needs in FreeCAD's own Python: NumPy (FreeCAD brings it) and
    cffi's backend, which the addon brings for CPython 3.8–3.13."""
    missing = []
    needs = ("numpy",) if bundled_backend_fits(wheels) else ("numpy", "_cffi_backend")
    for module in needs:
        try:
            __import__(module)
        except ImportError:
            missing.append(module)
    if missing:
        python = "Python %d.%d" % sys.version_info[:2]
        raise Refused("FreeCAD's %s lacks %s; install them for it (Debian/Ubuntu: apt install "
                      "python3-numpy python3-cffi-backend; elsewhere: pip install --target "
                      "%s numpy cffi, with pip of that Python)"
                      % (python, " and ".join(missing), additional_packages_dir()))


def additional_packages_dir():
    return os.path.join(FreeCAD.getUserAppDataDir(), "AdditionalPythonPackages")


def default_target():
    return os.path.join(FreeCAD.getUserAppDataDir(), "Mod", ADDON_NAME)


def copy_addon(source, target):
    """The addon folder into `target`, replacing an earlier RmfSurf there (and nothing
    else: a folder that is not this addon is refused)."""
    if os.path.exists(target):
        if package_name(target) != ADDON_NAME:
            raise Refused("%s exists and is not the %s addon; remove or rename it first"
                          % (target, ADDON_NAME))
        shutil.rmtree(target)
    shutil.copytree(source, target, ignore=shutil.ignore_patterns("__pycache__", "*.pyc"))


def unpack_wheel(wheel, target):
    """A wheel's files under `target` (its root holds rmfsurf/ and the dist-info; a wheel
    with a .data folder — scripts, headers — is not one of ours)."""
    with zipfile.ZipFile(wheel) as archive:
        names = archive.namelist()
        if any(n.split("/", 1)[0].endswith(".data") for n in names):
            raise Refused("%s has a .data folder; expected the rmfsurf wheel" % wheel)
        if not any(n.startswith("rmfsurf/") for n in names):
            raise Refused("%s holds no rmfsurf package" % wheel)
        archive.extractall(target)
    library = os.path.join(target, "rmfsurf", "_native")
    for name in os.listdir(library):
        if name.endswith(".so"):
            path = os.path.join(library, name)
            os.chmod(path, os.stat(path).st_mode | 0o755)


def copy_licenses(addon, source, target):
    """The license files the addon's package.xml names, from `source` into `target`."""
    for license in manifest(addon)("license"):
        name = license.get("file")
        shutil.copyfile(os.path.join(source, name), os.path.join(target, name))


def unpack_cffi_backends(wheels, target):
    """cffi's _cffi_backend extension from each cffi wheel in `wheels` into `target`, and
    cffi's license as LICENSE-cffi."""
    found = sorted(n for n in os.listdir(wheels) if n.startswith("cffi-") and n.endswith(".whl"))
    if not found:
        raise Refused("no cffi wheels in %s" % wheels)
    for name in found:
        with zipfile.ZipFile(os.path.join(wheels, name)) as archive:
            for member in archive.namelist():
                base = os.path.basename(member)
                if "/" not in member and base.startswith("_cffi_backend.") and base.endswith(".so"):
                    archive.extract(member, target)
                    os.chmod(os.path.join(target, base), 0o755)
    # Every wheel carries the same license; the first one's is taken.
    with zipfile.ZipFile(os.path.join(wheels, found[0])) as archive:
        (member,) = [m for m in archive.namelist()
                     if m.endswith(".dist-info/LICENSE") or m.endswith("licenses/LICENSE")]
        with archive.open(member) as src, open(os.path.join(target, "LICENSE-cffi"), "wb") as dst:
            shutil.copyfileobj(src, dst)


def version_of(addon):
    return manifest(addon)("version")[0].text.strip()


def install():
    source = os.environ["RMFSURF_ADDON_SOURCE"]
    wheel = os.environ["RMFSURF_WHEEL"]
    target = os.environ.get("RMFSURF_ADDON_INTO") or default_target()
    if package_name(source) != ADDON_NAME:
        raise Refused("%s is not the %s addon folder (no package.xml naming it)"
                      % (source, ADDON_NAME))
    wheel_version = os.path.basename(wheel).split("-")[1]
    if wheel_version != version_of(source):
        raise Refused("the wheel is rmfsurf %s, the addon (package.xml) %s"
                      % (wheel_version, version_of(source)))
    check_platform(wheel)
    check_python_modules(os.environ["RMFSURF_CFFI_WHEELS"])
    copy_addon(source, target)
    unpack_wheel(wheel, target)
    copy_licenses(source, os.environ["RMFSURF_LICENSES"], target)
    unpack_cffi_backends(os.environ["RMFSURF_CFFI_WHEELS"], target)
    say("FreeCAD %s, Python %d.%d, %s" % (".".join(FreeCAD.Version()[:3]),
                                          sys.version_info[0], sys.version_info[1],
                                          sysconfig.get_platform()))
    say("installed the %s addon %s with %s into %s"
        % (ADDON_NAME, version_of(target), os.path.basename(wheel), target))


def check():
    """In a fresh freecadcmd (which scanned the Mod folder at start-up): the workbench and
    the library load from the installed addon, at the addon's version."""
    import rmfsurf
    import rmfsurf_workbench
    target = default_target()
    where = os.path.dirname(os.path.dirname(os.path.abspath(rmfsurf.__file__)))
    if os.path.realpath(where) != os.path.realpath(target):
        raise Refused("rmfsurf loads from %s, not from the addon in %s" % (where, target))
    if rmfsurf.__version__ != rmfsurf_workbench.__version__:
        raise Refused("the library is %s, the workbench %s"
                      % (rmfsurf.__version__, rmfsurf_workbench.__version__))
    say("checked: import rmfsurf_workbench (%s) and rmfsurf %s from %s"
        % (rmfsurf_workbench.__version__, rmfsurf.__version__, target))


def main():
    try:
        check() if os.environ.get("RMFSURF_ADDON_CHECK") == "1" else install()
    except Refused as e:
        say("error: %s" % e)
        sys.exit(1)
    except SystemExit:
        raise
    except BaseException:
        traceback.print_exc()
        say("error: the installation failed (traceback above)")
        sys.exit(1)
    sys.exit(0)


main()
