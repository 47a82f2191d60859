#!/usr/bin/env python3
"""Checks that a file compiled for a wider instruction set than the build's exports nothing but
its entry points (backends/cpu/tile_renderer.h): every other function it defines, the inline
functions of the integrator, the standard library and oneTBB included, must be local to it, or
the linker could pick its AVX-512 copy of a function that code on any CPU calls.

    check_isa_object.py ARCHIVE MEMBER ENTRY...

ARCHIVE is the static library (libcandela_backends.a), MEMBER the object's name in it, ENTRY the
demangled names of the functions it may export. Exits 1, listing what else it exports."""
import subprocess
import sys

# The personality routine's reference: data that every C++ object with exceptions exports.
ALWAYS_EXPORTED = {'DW.ref.__gxx_personality_v0'}


def run(*command):
    return subprocess.run(command, check=True, capture_output=True, text=True).stdout


def main(argv):
    if len(argv) < 4:
        print('usage: check_isa_object.py ARCHIVE MEMBER ENTRY...', file=sys.stderr)
        return 2
    archive, member, entries = argv[1], argv[2], set(argv[3:])
    if member not in run('ar', 't', archive).split():
        print(f'{archive} has no member {member}', file=sys.stderr)
        return 1
    exported = []
    # Lines such as "libcandela_backends.a:render_tiles_x86_64_v4.cpp.o:0000000000000000 T name".
    for line in run('nm', '-A', '-C', '-g', '--defined-only', archive).splitlines():
        _, _, rest = line.partition(':')
        name_of_member, _, symbol = rest.partition(':')
        fields = symbol.split(' ', 2)
        if name_of_member != member or len(fields) < 3:
            continue
        kind, name = fields[1], fields[2]
        if name not in entries and name not in ALWAYS_EXPORTED:
            exported.append(f'{kind} {name}')
    if exported:
        print(f'{member} exports more than {", ".join(sorted(entries))}:', file=sys.stderr)
        for e in exported:
            print('  ' + e, file=sys.stderr)
        return 1
    print(f'{member} exports only {", ".join(sorted(entries))}')
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
