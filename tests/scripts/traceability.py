#!/usr/bin/env python3
"""Requirements traceability for TOLIP (issue 14; docs/verification/requirements.md).

The requirements file is the one mapping requirement -> tests. Each requirement is a heading
`### REQ-XXX-NNN title` followed by `- Source:`, `- Method:` and `- Tests:` lines; `Tests:` lists
CTest names separated by commas: a GoogleTest name `Suite.Test`, a suite `Suite.*`, or a script
test of add_test (shell-style wildcards allowed). A test source may also name requirements in a
comment `Verifies: REQ-XXX-NNN`.

  check   fails (exit 1) when a requirement lists no test, when a listed name matches no known
          test, when a requirement id is defined twice, when a test source names an id the
          file does not define, or when a test of the build traces to no requirement (neither
          listed on a `Tests:` line nor defined, `TEST(Suite, Name)`, in a source that names a
          requirement): traceability both ways, so that no test proves a function nobody asked for
          and no requirement goes without its proof.
  matrix  writes the matrix requirement -> tests -> last result (from ctest's JUnit output,
          `ctest --output-junit`) as Markdown.

Known tests: the build's (`ctest --test-dir BUILD --show-only=json-v1`) or a file of names
(--tests-file, one per line), plus every literal `add_test(NAME x` of the source tree (--source):
the Cortex-M7, MPI, fuzz and clean-clone tests exist only in their own configurations.
Only the Python standard library is used.
"""

import argparse
import fnmatch
import json
import os
import re
import subprocess
import sys
import xml.etree.ElementTree as ET

REQ_HEADING = re.compile(r"^###\s+(REQ-[A-Z]+-\d{3})\s+(.*)$")
FIELD = re.compile(r"^-\s+(Source|Method|Tests):\s*(.*)$")
TAG = re.compile(r"Verifies:\s*((?:REQ-[A-Z]+-\d{3}[\s,]*)+)")
TAG_ID = re.compile(r"REQ-[A-Z]+-\d{3}")
ADD_TEST = re.compile(r"add_test\(\s*NAME\s+([A-Za-z0-9_.+-]+)")
GTEST = re.compile(r"\bTEST(?:_F|_P)?\(\s*(\w+)\s*,\s*(\w+)\s*\)")
SKIP_DIRS = {".git", "__pycache__"}


def parse_requirements(path):
    """Returns (requirements, findings); requirements: list of dicts in file order."""
    reqs, findings, seen = [], [], set()
    current = None
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            line = line.rstrip("\n")
            m = REQ_HEADING.match(line)
            if m:
                current = {"id": m.group(1), "title": m.group(2).strip(), "line": number,
                           "Source": "", "Method": "", "Tests": []}
                if current["id"] in seen:
                    findings.append(f"{path}:{number}: {current['id']} is defined twice")
                seen.add(current["id"])
                reqs.append(current)
                continue
            if line.startswith("## ") or line.startswith("# "):
                current = None
                continue
            m = FIELD.match(line)
            if m and current is not None:
                if m.group(1) == "Tests":
                    current["Tests"] = [t.strip().strip("`") for t in m.group(2).split(",")
                                        if t.strip().strip("`")]
                else:
                    current[m.group(1)] = m.group(2).strip()
    return reqs, findings


def walk_files(root, suffixes):
    for base, dirs, files in os.walk(root):
        dirs[:] = [d for d in dirs if d not in SKIP_DIRS and not d.startswith("build")]
        for name in files:
            if name.endswith(suffixes):
                yield os.path.join(base, name)


def build_tests(build_dir):
    out = subprocess.run(["ctest", "--test-dir", build_dir, "--show-only=json-v1"],
                         check=True, capture_output=True, text=True).stdout
    return [t["name"] for t in json.loads(out).get("tests", [])]


def source_tests(source_dir):
    names = set()
    for path in walk_files(source_dir, ("CMakeLists.txt", ".cmake")):
        with open(path, encoding="utf-8", errors="replace") as f:
            names.update(ADD_TEST.findall(f.read()))
    return names


def tags(tag_dirs):
    """Returns {id: [file, ...]} for every `Verifies:` comment of the test sources."""
    found = {}
    for root in tag_dirs:
        for path in walk_files(root, (".cpp", ".hpp", ".h", ".cc", ".py", ".sh", ".cmake")):
            with open(path, encoding="utf-8", errors="replace") as f:
                text = f.read()
            for m in TAG.finditer(text):
                for rid in TAG_ID.findall(m.group(1)):
                    found.setdefault(rid, []).append(path)
    return found


def tagged_tests(tag_dirs):
    """Returns the GoogleTest names `Suite.Name` defined in the sources that carry a `Verifies:` tag."""
    found = set()
    for root in tag_dirs:
        for path in walk_files(root, (".cpp", ".cc")):
            with open(path, encoding="utf-8", errors="replace") as f:
                text = f.read()
            if TAG.search(text):
                found.update(f"{m.group(1)}.{m.group(2)}" for m in GTEST.finditer(text))
    return found


def matches(pattern, names):
    return sorted(n for n in names if fnmatch.fnmatchcase(n, pattern))


def known_tests(args):
    built = set()
    if args.tests_file:
        with open(args.tests_file, encoding="utf-8") as f:
            built.update(l.strip() for l in f if l.strip())
    if args.build:
        built.update(build_tests(args.build))
    declared = source_tests(args.source) if args.source else set()
    return built, declared


def check(args):
    reqs, findings = parse_requirements(args.requirements)
    built, declared = known_tests(args)
    every = built | declared
    ids = {r["id"] for r in reqs}
    for r in reqs:
        where = f"{args.requirements}:{r['line']}: {r['id']}"
        if not r["Tests"]:
            findings.append(f"{where} lists no test")
        if not r["Source"]:
            findings.append(f"{where} gives no source")
        if not r["Method"]:
            findings.append(f"{where} gives no verification method")
        for pattern in r["Tests"]:
            if not matches(pattern, every):
                findings.append(f"{where} names an unknown test: {pattern}")
    for rid, files in sorted(tags(args.tags).items()):
        if rid not in ids:
            findings.append(f"{files[0]}: names an unknown requirement: {rid}")
    traced = tagged_tests(args.tags) & built
    for r in reqs:
        for pattern in r["Tests"]:
            traced.update(matches(pattern, built))
    for name in sorted(built - traced):
        findings.append(f"{args.requirements}: test {name} traces to no requirement")
    for line in findings:
        print(line)
    if findings:
        print(f"traceability: {len(findings)} finding(s)")
        return 1
    print(f"traceability: {len(reqs)} requirements, each traced to a known test; "
          f"each of the {len(built)} tests of the build traces to a requirement")
    return 0


def junit_results(path):
    """Returns {test name: 'passed' | 'failed' | 'skipped' | 'not run'} from ctest's JUnit file."""
    results = {}
    for case in ET.parse(path).getroot().iter("testcase"):
        name = case.get("name")
        status = case.get("status", "run")
        if case.find("failure") is not None or case.find("error") is not None or status == "fail":
            results[name] = "failed"
        elif case.find("skipped") is not None or status == "disabled":
            results[name] = "skipped"
        elif status == "notrun":
            results[name] = "not run"
        else:
            results[name] = "passed"
    return results


def matrix(args):
    reqs, findings = parse_requirements(args.requirements)
    built, declared = known_tests(args)
    results = junit_results(args.junit) if args.junit else {}
    tagged = tags(args.tags)
    lines = ["# Traceability matrix", "",
             "Generated by `tests/scripts/traceability.py matrix` from "
             "[requirements.md](requirements.md) and ctest's JUnit output; do not edit by hand.",
             ""]
    if args.note:
        lines += [args.note, ""]
    totals = {"passed": 0, "failed": 0, "skipped": 0, "not run": 0, "names outside this build": 0}
    body = []
    for r in reqs:
        names = set()
        outside = []
        for pattern in r["Tests"]:
            hit = matches(pattern, built)
            if hit:
                names.update(hit)
            else:
                outside.append(pattern)
        counts = {}
        for n in names:
            state = results.get(n, "not run")
            counts[state] = counts.get(state, 0) + 1
        for state, c in counts.items():
            totals[state] += c
        totals["names outside this build"] += len(outside)
        verdict = ("FAILED" if counts.get("failed") else
                   "passed" if counts.get("passed") and not counts.get("not run") else
                   "incomplete" if counts.get("passed") else "not run")
        result = ", ".join(f"{c} {s}" for s, c in sorted(counts.items()))
        if outside:
            result += (", " if result else "") + f"{len(outside)} outside this build"
        tests = ", ".join(f"`{p}`" for p in r["Tests"])
        tagged_files = sorted({os.path.relpath(f, args.source or ".") for f in tagged.get(r["id"], [])})
        if tagged_files:
            tests += " (tagged in " + ", ".join(f"`{f}`" for f in tagged_files) + ")"
        body.append(f"| {r['id']} | {r['title']} | {r['Source']} | {r['Method'].split(' ')[0]} "
                    f"| {tests} | {len(names)} | {result or '-'} | {verdict} |")
    lines += [f"{len(reqs)} requirements; test results: "
              + ", ".join(f"{c} {s}" for s, c in totals.items() if c) + ".", "",
              "| id | requirement | source | method | tests | CTest tests | results | verdict |",
              "|---|---|---|---|---|---|---|---|"] + body
    text = "\n".join(lines) + "\n"
    if args.output:
        with open(args.output, "w", encoding="utf-8") as f:
            f.write(text)
    else:
        sys.stdout.write(text)
    for line in findings:
        print(line, file=sys.stderr)
    return 1 if findings else 0


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("mode", choices=["check", "matrix"])
    parser.add_argument("--requirements", required=True)
    parser.add_argument("--build", help="build directory: its ctest list is the known tests")
    parser.add_argument("--tests-file", help="file of known test names, one per line")
    parser.add_argument("--source", help="source tree whose add_test(NAME ...) count as known")
    parser.add_argument("--tags", action="append", default=[],
                        help="folder of test sources scanned for `Verifies: REQ-...` (repeatable)")
    parser.add_argument("--junit", help="ctest --output-junit file (matrix)")
    parser.add_argument("--output", help="matrix output file (default: stdout)")
    parser.add_argument("--note", help="a line printed under the matrix title (machine, date)")
    args = parser.parse_args()
    if not args.build and not args.tests_file:
        parser.error("give --build or --tests-file")
    return check(args) if args.mode == "check" else matrix(args)


if __name__ == "__main__":
    sys.exit(main())
