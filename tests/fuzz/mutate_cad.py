#!/usr/bin/env python3
"""Hostile CAD files: random byte edits, insertions and deletions of a STEP
or IGES file, each mutant run through `tpopt generate`; prints how many
crashed (killed by a signal), exited 1 or exited 0, and the crashing files.

  tests/fuzz/mutate_cad.py FILE COUNT SEED OUT_DIR [TPOPT]

Not run in CI (it takes about 0.3 s a file). The inputs of the README's
figures: tests/data/cad/five_faces.igs (five faces written by OCCT through
WriteCadPatches) and data/surfaces/impeller_blade.stp.
"""
import collections
import os
import random
import subprocess
import sys

source, count, seed, out_dir = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), sys.argv[4]
tpopt = sys.argv[5] if len(sys.argv) > 5 else 'build/tpopt'
os.makedirs(out_dir, exist_ok=True)
data = open(source, 'rb').read()
ext = os.path.splitext(source)[1]
rng = random.Random(seed)
alphabet = b'0123456789,;.-+EDH #()\n'
tally = collections.Counter()
for n in range(count):
    mutant = bytearray(data)
    for _ in range(rng.randint(1, 8)):
        op = rng.choice(('edit', 'insert', 'delete'))
        pos = rng.randrange(len(mutant))
        byte = rng.choice(alphabet) if rng.random() < 0.7 else rng.randrange(256)
        if op == 'edit':
            mutant[pos] = byte
        elif op == 'insert':
            mutant.insert(pos, byte)
        else:
            del mutant[pos]
    path = os.path.join(out_dir, 'm%03d%s' % (n, ext))
    open(path, 'wb').write(bytes(mutant))
    run = subprocess.run([tpopt, 'generate', '--surface=' + path, '--face=0',
                          '--cutter_radius=4', '--poses=20', '--strategy=spo',
                          '--out=' + os.path.join(out_dir, 'out.cls')],
                         stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                         timeout=120)
    kind = 'crash' if run.returncode < 0 else 'exit %d' % run.returncode
    tally[kind] += 1
    if run.returncode < 0:
        print(path, 'crash, signal', -run.returncode)
print(', '.join('%s %d' % (k, tally[k]) for k in ('crash', 'exit 1', 'exit 0')))
