#!/usr/bin/env python3
"""Reports the bare-metal controller image: its text/data/bss sizes and the stack depth of one
control cycle.

Usage: controller_image_report.py SIZE_TOOL IMAGE BUILD_DIR ROOT INDIRECT REPORT

The stack depth is the deepest path from ROOT (a function name, e.g. safecell::SafetyCycle::run)
through GCC's call graph: -fcallgraph-info=su writes every function's frame and calls into a .ci
file per object. An indirect call (the ports' virtual functions) counts as the deepest function
whose name holds INDIRECT (the image's port implementations). A function with no frame in the
graph (a compiler built-in, the compiler runtime) counts EXTERNAL_FRAME bytes. Recursion fails the
report (the core has none), except nanopb's decoder and encoder, which recurse once per level of
submessage nesting: safecell.v1's messages nest two levels (Message -> its body), so a cycle
through nanopb's own functions is counted NANOPB_EXTRA_LEVELS more times. A dynamic frame fails the report.
"""
import pathlib
import re
import subprocess
import sys

EXTERNAL_FRAME = 64
NANOPB_EXTRA_LEVELS = 2

NODE = re.compile(r'^node: \{ title: "([^"]+)" label: "([^"]*)"')
EDGE = re.compile(r'^edge: \{ sourcename: "([^"]+)" targetname: "([^"]+)"')
FRAME = re.compile(r'\\n(\d+) bytes \((static|dynamic)')


def main(size_tool, image, build_dir, root, indirect, report):
    sizes = subprocess.run([size_tool, image], check=True, capture_output=True, text=True).stdout
    frames, names, files, calls = {}, {}, {}, {}
    for graph in pathlib.Path(build_dir).rglob("*.ci"):
        for line in graph.read_text(errors="replace").splitlines():
            node = NODE.match(line)
            if node:
                title, label = node.groups()
                frame = FRAME.search(label)
                if frame:
                    if frame.group(2) == "dynamic":
                        sys.exit(f"{label.split(chr(92))[0]}: a dynamic stack frame")
                    frames[title] = int(frame.group(1))
                    names[title] = label.split("\\n")[0]
                    files[title] = label.split("\\n")[1] if "\\n" in label else ""
                continue
            edge = EDGE.match(line)
            if edge:
                calls.setdefault(edge.group(1), set()).add(edge.group(2))
    ports = [t for t, n in names.items() if indirect in n]
    roots = [t for t, n in names.items() if f" {root}(" in n or n.startswith(f"{root}(")]
    if not roots:
        sys.exit(f"{root} not found in the call graph under {build_dir}")

    memo, via = {}, {}

    def resolve(title):
        # A constructor or destructor alias (C1/C2, D1/D2) has its frame under the other name.
        if title in frames:
            return title
        alias = re.sub(r"([CD])1E", r"\g<1>2E", title)
        return alias if alias in frames else None

    def depth(title, path):
        known = resolve(title)
        if known is None:
            return EXTERNAL_FRAME
        title = known
        if title in path:
            if not all("nanopb" in files[t] for t in path[path.index(title):]):
                sys.exit(f"recursion through {names[title]}")
            cycle = path[path.index(title):]
            return NANOPB_EXTRA_LEVELS * sum(frames[t] for t in cycle)
        if title in memo:
            return memo[title]
        deepest, deepest_via = 0, None
        for callee in sorted(calls.get(title, ())):
            targets = ports if callee == "__indirect_call" else [callee]
            for target in targets:
                below = depth(target, path + [title])
                if below > deepest:
                    deepest, deepest_via = below, target
        memo[title] = frames[title] + deepest
        via[title] = deepest_via
        return memo[title]

    stack = depth(roots[0], [])
    lines, at, seen = [], roots[0], set()
    while at is not None and at not in seen:  # a nanopb recursion closes the path on itself
        seen.add(at)
        known = resolve(at)
        if known is None:
            lines.append(f"  {at} (external, counted as {EXTERNAL_FRAME} bytes)")
            break
        lines.append(f"  {names[known].split('(')[0]} ({frames[known]} bytes)")
        at = via.get(known)
    text = (f"The bare-metal controller image ({image}):\n{sizes}\n"
            f"Stack depth of one {root}: {stack} bytes, along\n" + "\n".join(lines) + "\n")
    pathlib.Path(report).write_text(text)
    print(text)


if __name__ == "__main__":
    if len(sys.argv) != 7:
        sys.exit(__doc__)
    main(*sys.argv[1:])
