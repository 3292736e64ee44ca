#!/usr/bin/env python3
"""Static worst-case stack bound of the Cortex-M7 flight image (docs/stack-usage.md).

Inputs:
  * the GCC call-graph files (-fcallgraph-info=su, one .ci per object): every function compiled from
    our sources (fsw_core, the flight demo, the start-up code) with its own frame size
    (-fstack-usage) and its direct callees;
  * the linked ELF, disassembled with objdump, for the functions that come precompiled from newlib
    and libgcc (sin, atan2, pow, memcpy, ...): their frame is bounded by adding up every push,
    vpush and "sub sp" in the function body (over-estimates when several paths push), and their
    callees are the targets of their bl / b instructions.

The bound of a function is its own frame plus the largest bound among its callees; the graph must
be acyclic (the core has no recursion, so a cycle fails the check).

An indirect call (a call through a function pointer: the start-up code's constructor loop, the
flight application's hal ports, the link's byte channel) may reach any function whose address the
image holds: the constructors listed between __init_array_start and __init_array_end (the linker
script keeps the .init_array input sections inside .text), and every function whose Thumb address
is a data word of the image (the literal pools and read-only data the disassembly shows as .word,
the initialized data of .data), the vector table excepted (its handlers are entered by exceptions,
accounted for by --handler). Every indirect call site is bounded by the deepest of them all.

A function GCC reports with a dynamic frame (alloca: Eigen's blocked triangular solves, built with
EIGEN_ALLOCA) is accepted only when its code in the linked image moves the stack pointer down by
constants alone (push, vpush, "sub sp, #N"; no "sub sp, rN"): its frame is then bounded by all of
them added up, as if every allocation were taken at once.

Checks: the bound from --root fits in the reserved stack (--stack-size, by default the image's
__stack_top - __stack_limit) and covers the high-water mark measured on the target (--measured: a
file holding the image's "stack high-water N bytes" line from a QEMU run: the demo's "TARGET stack
high-water", the PIL image's "PIL END ... stack high-water").
"""
import argparse
import os
import re
import subprocess
import sys
from functools import lru_cache

NODE = re.compile(r'^node: \{ title: "([^"]+)" label: "((?:[^"\\]|\\.)*)"')
EDGE = re.compile(r'^edge: \{ sourcename: "([^"]+)" targetname: "([^"]+)"')
FRAME = re.compile(r'\\n(\d+) bytes \(([a-z, ]+)\)$')


def read_call_graph(ci_dir, exclude=()):
    frames, labels, qualifiers, callees = {}, {}, {}, {}
    for root, dirs, files in os.walk(ci_dir):
        dirs[:] = [d for d in dirs if d not in exclude]  # another image's objects (same symbol names)
        for name in files:
            if not name.endswith(".ci"):
                continue
            with open(os.path.join(root, name), encoding="utf-8", errors="replace") as f:
                for line in f:
                    m = NODE.match(line)
                    if m:
                        title, label = m.group(1), m.group(2)
                        fm = FRAME.search(label)
                        labels.setdefault(title, label.split("\\n")[0])
                        if fm:
                            size = int(fm.group(1))
                            if size >= frames.get(title, -1):
                                frames[title] = size
                                qualifiers[title] = fm.group(2)
                        continue
                    m = EDGE.match(line)
                    if m:
                        callees.setdefault(m.group(1), set()).add(m.group(2))
    return frames, labels, qualifiers, callees


def disassemble(objdump, elf):
    out = subprocess.run([objdump, "-d", "--no-show-raw-insn", elf], check=True, capture_output=True,
                         text=True).stdout
    functions, current, words = {}, None, set()
    header = re.compile(r'^[0-9a-f]+ <([^>]+)>:$')
    section = None
    for line in out.splitlines():
        if line.startswith("Disassembly of section "):
            section = line[len("Disassembly of section "):].rstrip(":")
            continue
        m = header.match(line)
        if m:
            current = m.group(1)
            # Two local functions of the same name (different objects) add up: an over-estimate.
            functions.setdefault(current, {"frame": 0, "calls": set(), "indirect": False, "sp_by_register": False,
                                           "movt": False})
            continue
        if current is None or "\t" not in line:
            continue
        parts = line.split("\t")
        if len(parts) < 2:
            continue
        mnemonic = parts[1].strip()
        operands = parts[2].strip() if len(parts) > 2 else ""
        if mnemonic == ".word":
            if section != ".vectors":
                words.add(int(operands.split()[0], 16))  # a literal pool or read-only data word
            continue
        f = functions[current]
        if mnemonic.startswith("movt"):
            f["movt"] = True  # an address built in registers would escape the data-word scan
        if mnemonic in ("push", "push.w", "stmdb") and ("sp!" in operands or mnemonic.startswith("push")):
            regs = operands[operands.find("{") + 1:operands.find("}")]
            f["frame"] += 4 * count_registers(regs)
        elif mnemonic in ("vpush", "vstmdb") and ("sp!" in operands or mnemonic == "vpush"):
            regs = operands[operands.find("{") + 1:operands.find("}")]
            f["frame"] += 8 * count_registers(regs)
        elif mnemonic.startswith("sub") and re.match(r'^sp,\s*(sp,\s*)?#', operands):
            f["frame"] += int(re.search(r'#(\d+)', operands).group(1))
        elif mnemonic.startswith("sub") and re.match(r'^sp,\s*(sp,\s*)?[a-z]', operands):
            f["sp_by_register"] = True  # a stack allocation of run-time size
        elif mnemonic.startswith("str") and operands.startswith("") and "[sp, #-" in operands and "]!" in operands:
            f["frame"] += int(re.search(r'\[sp, #-(\d+)\]!', operands).group(1))
        m = re.search(r'<([^>+]+)>$', operands)
        if mnemonic in ("bl", "blx") and m:
            f["calls"].add(m.group(1))
        elif mnemonic in ("b", "b.w", "b.n") and m and m.group(1) != current:
            f["calls"].add(m.group(1))  # tail call (or a branch into another function)
        elif mnemonic == "blx" and not m:
            f["indirect"] = True
    return functions, words


def symbol_table(objdump, elf):
    """Addresses by name and function names by (even) address, from nm."""
    symbols = subprocess.run([objdump.replace("objdump", "nm"), elf], check=True, capture_output=True,
                             text=True).stdout
    by_address, by_name, functions = {}, {}, {}
    for line in symbols.splitlines():
        p = line.split()
        if len(p) == 3:
            by_address.setdefault(int(p[0], 16) & ~1, p[2])
            by_name[p[2]] = int(p[0], 16)
            if p[1] in "Tt" and not p[2].startswith("$"):
                functions.setdefault(int(p[0], 16) & ~1, p[2])
    return by_address, by_name, functions


def data_words(objdump, elf, sections):
    """The aligned little-endian words of the named sections (initialized data)."""
    words = set()
    for name in sections:
        out = subprocess.run([objdump, "-s", "-j", name, elf], capture_output=True, text=True).stdout
        data, base = b"", None
        for line in out.splitlines():
            m = re.match(r'^ ([0-9a-f]+) ((?:[0-9a-f]{2,8} ?)+)', line)
            if m:
                if base is None:
                    base = int(m.group(1), 16)
                data += bytes.fromhex("".join(m.group(2).split()))
        if base is None:
            continue
        first = (-base) % 4
        for i in range(first, len(data) - 3, 4):
            words.add(int.from_bytes(data[i:i + 4], "little"))
    return words


def address_taken_functions(objdump, elf, literal_words):
    """Functions whose Thumb address (bit 0 set) is a data word of the image, vectors excepted."""
    _, _, functions = symbol_table(objdump, elf)
    words = set(literal_words) | data_words(objdump, elf, [".data"])
    return sorted({functions[w & ~1] for w in words if w & 1 and (w & ~1) in functions})


def reserved_stack(objdump, elf):
    _, by_name, _ = symbol_table(objdump, elf)
    if "__stack_top" not in by_name or "__stack_limit" not in by_name:
        raise SystemExit("no __stack_top/__stack_limit in " + elf + ": give --stack-size")
    return by_name["__stack_top"] - by_name["__stack_limit"]


def count_registers(text):
    count = 0
    for item in text.split(","):
        item = item.strip()
        r = re.match(r'^([rds])(\d+)-[rds]?(\d+)$', item)
        if r:
            count += int(r.group(3)) - int(r.group(2)) + 1
        elif item:
            count += 1
    return count


def init_array_functions(objdump, elf):
    by_address, by_name, _ = symbol_table(objdump, elf)
    start, end = by_name.get("__init_array_start"), by_name.get("__init_array_end")
    if start is None or end is None:
        raise SystemExit("no __init_array_start/__init_array_end in " + elf)
    if end <= start:
        return []
    out = subprocess.run([objdump, "-s", f"--start-address={start:#x}", f"--stop-address={end:#x}", elf],
                         check=True, capture_output=True, text=True).stdout
    data = b""
    for line in out.splitlines():
        m = re.match(r'^ ([0-9a-f]+) ((?:[0-9a-f]{2,8} ?)+)', line)
        if m:
            data += bytes.fromhex("".join(m.group(2).split()))
    data = data[:end - start]
    words = [int.from_bytes(data[i:i + 4], "little") & ~1 for i in range(0, len(data), 4)]
    return [by_address.get(w, hex(w)) for w in words]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--ci-dir", required=True)
    parser.add_argument("--exclude-dir", action="append", default=[],
                        help="directory names under --ci-dir to skip (the objects of another image)")
    parser.add_argument("--elf", required=True)
    parser.add_argument("--objdump", required=True)
    parser.add_argument("--root", required=True)
    parser.add_argument("--also", action="append", default=[], help="other roots to report")
    parser.add_argument("--handler", action="append", default=[],
                        help="exception handlers that may run on top of the deepest chain")
    parser.add_argument("--stack-size", type=int,
                        help="the reserved stack in bytes (default: __stack_top - __stack_limit of --elf)")
    parser.add_argument("--measured")
    parser.add_argument("--report")
    args = parser.parse_args()

    frames, labels, qualifiers, callees = read_call_graph(args.ci_dir, args.exclude_dir)
    binary, literal_words = disassemble(args.objdump, args.elf)
    constructors = init_array_functions(args.objdump, args.elf)
    address_taken = [f for f in address_taken_functions(args.objdump, args.elf, literal_words)
                     if f not in constructors]
    indirect_targets = constructors + address_taken
    if args.stack_size is None:
        args.stack_size = reserved_stack(args.objdump, args.elf)
    problems = [f"{name}: movw/movt in the image: a function address built in registers escapes the "
                f"indirect-call scan" for name, f in binary.items() if f["movt"]]

    def symbol(name):
        return name.rsplit(":", 1)[-1]  # .ci titles of file-local functions are "path:symbol"

    def frame_of(name):
        if name in frames:
            if "dynamic" in qualifiers.get(name, "static") and symbol(name) in binary:
                return max(frames[name], binary[symbol(name)]["frame"]), "ci+"
            return frames[name], "ci"
        if name in binary:
            return binary[name]["frame"], "elf"
        return None, "none"

    def callees_of(name):
        if name in frames:
            result = set(callees.get(name, set()))
            if "__indirect_call" in result:
                result.discard("__indirect_call")
                result.update(indirect_targets)
            return result
        if name in binary:
            if binary[name]["indirect"]:
                problems.append(f"{name}: indirect call in library code")
            return binary[name]["calls"]
        return set()

    visiting = set()
    dynamic_frames = set()

    @lru_cache(maxsize=None)
    def bound(name):
        if name in visiting:
            problems.append(f"recursion through {name}")
            return 0, (name,)
        visiting.add(name)
        own, source = frame_of(name)
        if own is None:
            own = 0  # a builtin expanded inline (never emitted) or a symbol absent from the image
        if qualifiers.get(name, "static") not in ("static",):
            linked = binary.get(symbol(name))
            if linked is None or linked["sp_by_register"]:
                if "bounded" not in qualifiers[name]:
                    problems.append(f"{name}: dynamic stack ({qualifiers[name]})")
            else:
                dynamic_frames.add(name)
        best, chain = 0, ()
        for callee in sorted(callees_of(name)):
            if callee == name:
                problems.append(f"recursion in {name}")
                continue
            b, c = bound(callee)
            if b > best:
                best, chain = b, c
        visiting.discard(name)
        return own + best, (name,) + chain

    def label(name):
        text = labels.get(name, name)
        return symbol(name) if re.match(r'^\d', text) else text  # GCC mislabels .part clones

    def reachable(root):
        seen, todo = set(), [root]
        while todo:
            n = todo.pop()
            if n in seen:
                continue
            seen.add(n)
            todo.extend(callees_of(n))
        return seen

    lines = []
    total, chain = bound(args.root)
    lines.append(f"Static worst-case stack bound from {args.root}: {total} bytes (stack region {args.stack_size} bytes)")
    lines.append("Deepest call chain (own frame in bytes, source of the figure):")
    for name in chain:
        own, source = frame_of(name)
        lines.append(f"  {own if own is not None else 0:6d}  [{source:4s}] {label(name)}")
    for root in args.also:
        b, c = bound(root)
        lines.append(f"Bound from {label(root)}: {b} bytes ({len(c)} frames deep)")
    # An exception taken at the deepest point stacks an extended (FPU) frame of 26 words, then runs
    # its handler on the same (main) stack.
    if args.handler:
        handler_bound = max(bound(h)[0] for h in args.handler)
        exception_frame = 104
        lines.append(f"Plus the deepest exception handler ({handler_bound} bytes) and its FPU exception frame "
                     f"({exception_frame} bytes): {total + handler_bound + exception_frame} bytes")
        total += handler_bound + exception_frame
    callers = sorted(label(n) for n in reachable(args.root) if "__indirect_call" in callees.get(n, ()))
    lines.append("Indirect call sites reached: " + (", ".join(callers) if callers else "none"))
    lines.append("Constructors (.init_array): "
                 + (", ".join(f"{c} ({bound(c)[0]} bytes)" for c in constructors) if constructors else "none"))
    lines.append("Other address-taken functions (indirect call targets): "
                 + (", ".join(f"{label(f)} ({bound(f)[0]} bytes)" for f in address_taken)
                    if address_taken else "none"))
    for name in sorted(dynamic_frames):
        lines.append(f"Dynamic frame bounded from the image (constant-size allocations only): "
                     f"{frame_of(name)[0]} bytes [ci+] {label(name)}")

    measured = None
    if args.measured:
        with open(args.measured, encoding="utf-8", errors="replace") as f:
            m = re.search(r'stack high-water (\d+) bytes', f.read())
        if not m:
            problems.append("no 'stack high-water N bytes' line in " + args.measured)
        else:
            measured = int(m.group(1))
            lines.append(f"Measured high-water mark on the target (painted stack, QEMU run): {measured} bytes")
    lines.append(f"BOUND {total} bytes")
    if total > args.stack_size:
        problems.append(f"the bound {total} exceeds the stack region {args.stack_size}")
    if measured is not None and measured > total:
        problems.append(f"the measured high-water mark {measured} exceeds the static bound {total}")

    text = "\n".join(lines) + "\n"
    if problems:
        text += "PROBLEMS:\n" + "".join(f"  {p}\n" for p in sorted(set(problems)))
    if args.report:
        with open(args.report, "w", encoding="utf-8") as f:
            f.write(text)
    print(text, end="")
    if problems:
        print("FAIL")
        return 1
    print("OK")
    return 0


if __name__ == "__main__":
    sys.exit(main())
