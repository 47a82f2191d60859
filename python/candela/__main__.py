"""`python -m candela ...`: the candela command line (the C++ CLI installed with the package)."""
import os
import shutil
import sys
import sysconfig


def main() -> int:
    exe = os.path.join(sysconfig.get_path("scripts"), "candela")
    if not os.path.isfile(exe):
        exe = shutil.which("candela") or exe
    os.execv(exe, [exe] + sys.argv[1:])
    return 1  # not reached


if __name__ == "__main__":
    sys.exit(main())
