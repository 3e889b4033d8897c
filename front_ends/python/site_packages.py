# Prints where the Python package is installed, relative to the prefix given:
# the interpreter's own site-packages when it lies under that prefix (Debian,
# /usr/local: lib/python3.X/dist-packages), else the standard prefix layout.
import os
import sys
import sysconfig

prefix = os.path.abspath(sys.argv[1])
platlib = os.path.abspath(sysconfig.get_path("platlib"))
if os.path.commonpath([platlib, prefix]) == prefix:
    print(os.path.relpath(platlib, prefix))
else:
    print(sysconfig.get_path("platlib", "posix_prefix", vars={"base": prefix, "platbase": prefix})[len(prefix) + 1:])
