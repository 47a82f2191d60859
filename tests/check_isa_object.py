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


def main(argv):
    if len(argv) < 4:
        print(__doc__.strip().splitlines()[-4], file=sys.stderr)
        return 2
    archive, member, entries = argv[1], argv[2], set(argv[3:])
    out = subprocess.run(['nm', '-A', '-C', '-g', '--defined-only', archive], check=True,
                         capture_output=True, text=True).stdout
    found = False
    exported = []
    for line in out.splitlines():
        # libcandela_backends.a:render_tiles_x86_64_v4.cpp.o:0000000000000000 T name(args)
        head, _, rest = line.partition(':')
        name_of_member, _, symbol = rest.partition(':')
        if name_of_member != member:
            continue
        found = True
        fields = symbol.split(' ', 2)
        if len(fields) < 3:
            continue
        kind, name = fields[1], fields[2]
        # Code (T, W, i) or data that code could be reached through (V: a weak object, u: a
        # unique global). The personality routine's reference is data every C++ object exports.
        if name == 'DW.ref.__gxx_personality_v0':
            continue
        if name not in entries:
            exported.append(f'{kind} {name}')
    if not found:
        # An object that defines nothing global does not appear; nm lists every member it reads
        # only with symbols, so look for the member itself.
        members = subprocess.run(['ar', 't', archive], check=True, capture_output=True,
                                 text=True).stdout.split()
        if member not in members:
            print(f'{archive} has no member {member}', file=sys.stderr)
            return 1
    if exported:
        print(f'{member} exports more than {", ".join(sorted(entries))}:', file=sys.stderr)
        for e in exported:
            print('  ' + e, file=sys.stderr)
        return 1
    print(f'{member} exports only {", ".join(sorted(entries))}')
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
