#!/usr/bin/env python3
"""Where ffx-dof's time goes on lavapipe, down to the JIT-compiled functions.

lavapipe (llvmpipe) compiles each shader with LLVM into anonymous executable memory, without symbols,
so `perf report` shows one unnamed blob. This tool runs `ffx-dof bench` for long enough, samples it
with `perf record -e cpu-clock`, copies the JIT memory out of the live process with gdb, disassembles it
with objdump, cuts it into functions at their `ret`s and prints the share of the samples in each,
largest first. Each shader is one large function; on Mesa 22.3 its texel fetches of images whose format
is not an RGBA8 variant are calls to small helpers of their own (a few hundred instructions around a
gather: `vpgatherdd`, or per-lane loads, `vpinsr*`, for 16- and 64-bit texels), which the table tells by
their size and those instructions. Which shader a large function is follows from its size and share
(the blur's is the largest).

    python3 tools/profile-lavapipe.py [--bin build/default/tools/cli/ffx-dof] [--seconds 8] [--top 12]
        [--annotate DIR] [-- bench options, e.g. --width 1920 --height 1080 --quality 10 --float32]

With --annotate, each printed function's disassembly goes to DIR/function-RANK.txt with its samples per
instruction: a group-shared read shows there as a loop over the lanes whose stores to the stack and reloads
(one per 32-bit component) take most of the samples.

Needs perf (linux-perf), gdb and objdump (tools/setup.sh installs them) and permission to trace the
process (root, or kernel.perf_event_paranoid <= 1 and ptrace allowed). Shares are of one process, so
they compare the parts of one run with each other; compare builds by their shares, not by sample
counts (docs/performance.md, "Where the time goes on lavapipe").
"""
import argparse
import bisect
import collections
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time

INSTRUCTION = re.compile(r"\s+([0-9a-f]+):\s+(?:[0-9a-f]{2} )+\s*(.*)")


def fail(message):
    print(f"profile-lavapipe: {message}", file=sys.stderr)
    sys.exit(1)


def executable_anonymous_mappings(pid):
    """(start, end) of every anonymous executable mapping of the process: the JIT's code."""
    mappings = []
    with open(f"/proc/{pid}/maps") as maps:
        for line in maps:
            fields = line.split()
            # address perms offset dev inode [path]; the JIT's memory has no path.
            if len(fields) == 5 and "x" in fields[1]:
                start, end = (int(x, 16) for x in fields[0].split("-"))
                mappings.append((start, end))
    return mappings


def disassemble(path, start):
    out = subprocess.run(["objdump", "-D", "-b", "binary", "-m", "i386:x86-64", f"--adjust-vma={start:#x}", path],
                         capture_output=True, text=True, check=True).stdout
    instructions = []
    for line in out.splitlines():
        match = INSTRUCTION.match(line)
        if match:
            instructions.append((int(match.group(1), 16), match.group(2).strip()))
    return instructions


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--bin", default="build/default/tools/cli/ffx-dof", help="the ffx-dof CLI to profile")
    parser.add_argument("--seconds", type=float, default=8.0, help="how long to sample, after the warm-up")
    parser.add_argument("--warmup", type=float, default=5.0, help="seconds of bench before sampling starts")
    parser.add_argument("--top", type=int, default=12, help="functions to print")
    parser.add_argument("--annotate", metavar="DIR",
                        help="also write each printed function's disassembly with its samples per instruction to "
                             "DIR/function-RANK.txt (the hot loops of a shader)")
    parser.add_argument("bench_args", nargs="*", help="options for `ffx-dof bench` (after --)")
    args = parser.parse_args()

    for tool in ("perf", "gdb", "objdump"):
        if shutil.which(tool) is None:
            fail(f"{tool} not found; run tools/setup.sh")
    if not os.access(args.bin, os.X_OK):
        fail(f"{args.bin} is not an executable; build it first (cmake --build --preset default --target ffx-dof)")
    with tempfile.TemporaryDirectory(prefix="profile-lavapipe-") as work:
        env = dict(os.environ)
        if not env.get("XDG_RUNTIME_DIR"):
            env["XDG_RUNTIME_DIR"] = work  # created 0700, as the Vulkan loader wants it
        bench = subprocess.Popen([args.bin, "bench", "--repeat", "10000", *args.bench_args], env=env,
                                 stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        try:
            time.sleep(args.warmup)
            if bench.poll() is not None:
                fail(f"ffx-dof bench ended early (exit {bench.returncode}): {bench.stderr.read().strip()}")
            samples_path = os.path.join(work, "perf.data")
            record = subprocess.run(["perf", "record", "-e", "cpu-clock", "-F", "4000", "-p", str(bench.pid), "-o",
                                     samples_path, "--", "sleep", str(args.seconds)], capture_output=True, text=True)
            if record.returncode != 0 or not os.path.exists(samples_path):
                fail(f"perf record failed: {record.stderr.strip()}")
            mappings = executable_anonymous_mappings(bench.pid)
            if not mappings:
                fail("the bench process has no anonymous executable memory (is the device lavapipe?)")
            dumps = []
            commands = []
            for start, end in mappings:
                path = os.path.join(work, f"jit-{start:x}.bin")
                dumps.append((start, end, path))
                commands += ["-ex", f"dump binary memory {path} {start:#x} {end:#x}"]
            subprocess.run(["gdb", "-p", str(bench.pid), "-batch", *commands, "-ex", "detach"],
                           capture_output=True, text=True)
        finally:
            bench.send_signal(signal.SIGTERM)
            bench.wait()

        script = subprocess.run(["perf", "script", "-i", samples_path, "-F", "ip"], capture_output=True, text=True)
        ips = collections.Counter(int(x, 16) for x in script.stdout.split())
        total = sum(ips.values())
        if total == 0:
            fail("perf recorded no samples")

        # Functions: from the start of a mapping or the instruction after a `ret` to the next.
        starts = []
        kinds = collections.defaultdict(collections.Counter)  # per function: gathers, per-lane loads
        listing = []  # every instruction of every mapping, in address order per mapping
        for start, end, path in dumps:
            if not os.path.exists(path):
                fail(f"gdb could not read {start:#x}-{end:#x} (ptrace not allowed?)")
            instructions = disassemble(path, start)
            listing += instructions
            function = start
            starts.append(function)
            for i, (_, text) in enumerate(instructions):
                if text.startswith("vpgather") or text.startswith("vgather"):
                    kinds[function]["gathers"] += 1
                elif text.startswith("vpinsr"):
                    kinds[function]["lane loads"] += 1
                if text.startswith("ret") and i + 1 < len(instructions):
                    function = instructions[i + 1][0]
                    starts.append(function)
            starts.append(end)
        starts.sort()
        per_function = collections.Counter()
        outside = 0
        for ip, count in ips.items():
            i = bisect.bisect_right(starts, ip) - 1
            if i < 0 or i + 1 >= len(starts) or not any(s <= ip < e for s, e, _ in dumps):
                outside += count
            else:
                per_function[starts[i]] += count
        print(f"{total} samples over {args.seconds:g} s; {100.0 * outside / total:.1f}% outside the JIT code "
              "(lavapipe, the driver, the kernel)")
        print(f"{'rank':>4} {'bytes':>7} {'share':>6} {'gathers':>7} {'lane loads':>10}")
        for rank, (function, count) in enumerate(per_function.most_common(args.top)):
            size = starts[starts.index(function) + 1] - function
            print(f"{rank:>4} {size:>7} {100.0 * count / total:5.1f}% {kinds[function]['gathers']:>7} "
                  f"{kinds[function]['lane loads']:>10}")
            if args.annotate:
                os.makedirs(args.annotate, exist_ok=True)
                with open(os.path.join(args.annotate, f"function-{rank}.txt"), "w") as out:
                    out.write(f"# rank {rank}: {size} bytes at {function:#x}, {count} of {total} samples\n")
                    for address, text in listing:
                        if function <= address < function + size:
                            out.write(f"{ips.get(address, 0):>7} {address:#x} {text}\n")


if __name__ == "__main__":
    main()
