"""Where `meson install` puts acbb.py: a site directory the python3 found at
configure time searches (meson.build runs this with that interpreter).

Usage: python3 site_dir.py PREFIX MESON_DIR
Prints one absolute directory:
1. MESON_DIR (meson's python.get_install_dir() for PREFIX) when this
   interpreter searches it: Debian's python3 with prefix /usr
   (/usr/lib/python3/dist-packages), a venv, a prefix of ~/.local (the user
   site directory);
2. else the first directory it searches under PREFIX: Debian's python3 with
   /usr/local searches /usr/local/lib/python3.X/dist-packages, not the
   /usr/local/lib/python3/dist-packages meson names;
3. else its own site directory (sysconfig purelib), outside PREFIX: pyenv's
   python3 searches only ~/.pyenv/versions/V/lib/python3.X/site-packages,
   and meson's /usr/local/lib/python3.X/site-packages is searched by no
   interpreter there. pip installs there too.
"Searches" is the site module's list (site.getsitepackages() and the user
site directory), whether or not the directory exists yet; PYTHONPATH is not
counted (it is the configuring shell's, not the user's).
"""
import os
import site
import sys
import sysconfig


def searched():
    dirs = list(site.getsitepackages()) if hasattr(site, "getsitepackages") else []
    if site.ENABLE_USER_SITE:
        dirs.append(site.getusersitepackages())
    return [os.path.normpath(d) for d in dirs]


def choose(prefix, meson_dir, dirs, purelib):
    prefix, meson_dir = os.path.normpath(prefix), os.path.normpath(meson_dir)
    if meson_dir in dirs:
        return meson_dir
    for d in dirs:
        if d.startswith(prefix.rstrip(os.sep) + os.sep):
            return d
    return os.path.normpath(purelib)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: site_dir.py PREFIX MESON_DIR")
    print(choose(sys.argv[1], sys.argv[2], searched(), sysconfig.get_paths()["purelib"]))
