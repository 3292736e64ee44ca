#!/usr/bin/env python3
"""The uncovered branches of fsw_core, sorted by the kind of line they sit on.

Reads the gcovr JSON that scripts/coverage.sh writes (build-coverage/coverage/coverage.json) and the
sources it names, and prints, per kind, the number of branches never taken and the files and lines
that hold most of them. The kinds are those docs/verification/coverage.md explains (why each is or
is not worth a test); a line is put in the first kind whose rule matches its text:

  finite      std::isfinite / allFinite / all_finite: GCC compiles each into two jumps (NaN, inf)
  propagate   a failure passed on: `if (!ok(...)) return`, TOLIP_CHECK, `return status` chains
  null-guard  an optional or guarded pointer: `== nullptr` / `!= nullptr`
  switch-arm  a switch over an enum (its `default:` and `case` arms)
  other       everything else: reachable, not yet tested (the next tests worth writing)

  scripts/coverage_gaps.py [COVERAGE_JSON]
"""
import collections
import json
import os
import re
import sys

KINDS = [
    ("finite", re.compile(r"isfinite|allFinite|all_finite")),
    ("propagate", re.compile(r"!ok\(|TOLIP_CHECK|return status;|return s;|if \(!ok")),
    ("null-guard", re.compile(r"[!=]= nullptr|nullptr [!=]=")),
    ("switch-arm", re.compile(r"^\s*(default:|case\s)|switch \(")),
]


def kind_of(text):
    for name, rule in KINDS:
        if rule.search(text):
            return name
    return "other"


def main():
    path = sys.argv[1] if len(sys.argv) > 1 else "build-coverage/coverage/coverage.json"
    data = json.load(open(path))
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(path))))
    counts = collections.Counter()
    places = collections.defaultdict(collections.Counter)
    total = 0
    for record in data["files"]:
        name = record["file"]
        source_path = name if os.path.isabs(name) else os.path.join(root, name)
        try:
            lines = open(source_path).read().splitlines()
        except OSError:
            lines = []
        for line in record["lines"]:
            missed = sum(1 for b in line["branches"] if b["count"] == 0 and not b.get("throw", False))
            if missed == 0:
                continue
            number = line["line_number"]
            text = lines[number - 1] if 0 < number <= len(lines) else ""
            kind = kind_of(text)
            counts[kind] += missed
            places[kind][f"{os.path.relpath(source_path, root)}:{number}"] += missed
            total += missed
    print(f"{total} branches of fsw_core never taken, by the kind of line they sit on")
    for name, _ in KINDS + [("other", None)]:
        print(f"\n{name}: {counts[name]}")
        by_file = collections.Counter()
        for place, n in places[name].items():
            by_file[place.rsplit(":", 1)[0]] += n
        for file_name, n in by_file.most_common(8):
            print(f"  {n:4d}  {file_name}")


if __name__ == "__main__":
    main()
