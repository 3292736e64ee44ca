#!/usr/bin/env python3
"""Robustness check of the heritage card-deck reader (issue 6: "no input, however malformed,
crashes the reader"). Mutates examples/scout/mission.dat (truncated, corrupted, deleted,
duplicated, padded and blanked cards; numbers replaced by '-', '.', 'E', '1.0E10', '999',
'E+99', 'nan') and runs `tolip convert` and `tolip simulate` on each deck. Any death by signal
or an exit code outside the documented 0-2 is reported and the deck kept as crash_*.dat.
Not part of CTest (about 2 minutes for 250 decks on the 2-core VM).

  tests/scripts/fuzz_card_decks.py build/ground_tools/tolip [SEED] [COUNT]
"""
import os
import random
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def mutate(lines, rng):
    lines = list(lines)
    for _ in range(rng.randint(1, 6)):
        k = rng.randrange(len(lines))
        op = rng.randrange(7)
        if op == 0:
            lines[k] = lines[k][:rng.randrange(len(lines[k]) + 1)]
        elif op == 1 and lines[k]:
            j = rng.randrange(len(lines[k]))
            lines[k] = lines[k][:j] + bytes([rng.randrange(256)]) + lines[k][j + 1:]
        elif op == 2:
            del lines[k]
        elif op == 3:
            lines.insert(k, lines[rng.randrange(len(lines))])
        elif op == 4:
            lines[k] = lines[k] + b'9' * rng.randrange(100)
        elif op == 5 and lines[k]:
            j = rng.randrange(len(lines[k]))
            token = rng.choice([b'-', b'.', b'E', b'1.0E10', b' ', b'999', b'E+99', b'nan'])
            lines[k] = lines[k][:j] + token + lines[k][j + 1:]
        else:
            lines[k] = b''
    return lines


def main():
    tolip = sys.argv[1]
    rng = random.Random(int(sys.argv[2]) if len(sys.argv) > 2 else 1)
    count = int(sys.argv[3]) if len(sys.argv) > 3 else 250
    with open(os.path.join(ROOT, 'examples', 'scout', 'mission.dat'), 'rb') as f:
        lines = f.read().split(b'\n')
    crashes = 0
    with tempfile.TemporaryDirectory() as scratch:
        deck = os.path.join(scratch, 'deck.dat')
        for i in range(count):
            data = b'\n'.join(mutate(lines, rng))
            with open(deck, 'wb') as f:
                f.write(data)
            for command in (['convert', deck, '--to', os.path.join(scratch, 'out.toml')], ['simulate', deck, '--json']):
                run = subprocess.run([tolip] + command, capture_output=True, timeout=60)
                if run.returncode < 0 or run.returncode > 2:
                    crashes += 1
                    with open(f'crash_{i}_{command[0]}.dat', 'wb') as f:
                        f.write(data)
                    print(f'CRASH deck {i} {command[0]} exit {run.returncode}: {run.stderr[-300:]!r}')
    print(f'{count} decks, {crashes} crashes')
    return 1 if crashes else 0


if __name__ == '__main__':
    sys.exit(main())
