#!/usr/bin/env python3
"""Draws doc/img/structure.svg: the project's libraries as boxes on floors and their link
dependencies as arrows, read from the `DEPS simp::X` of every libs/*/CMakeLists.txt (the build's
own declaration, so the picture is the code's). A library stands one floor above the highest
library it depends on; arrows point from a library to what it uses; an arrow implied by a path
through other libraries is left out (transitive reduction; the full lists are in
doc/architecture.md "Libraries"). Shared plugins are drawn in orange. First it checks that every
`#include <simp/X/...>` in libs/Y is of a library Y's DEPS reach (else it names the file and stops).
Standard library only.
  python3 doc/tools/structure_svg.py [--check]     (from the repository root)
--check compares with the committed picture and exits 1 when it differs."""
import pathlib, re, sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
OUT = ROOT / "doc" / "img" / "structure.svg"
BOX_W, BOX_H, GAP_X, FLOOR_H, MARGIN = 118, 34, 26, 92, 20


def read_libraries():
    libs = {}
    for cm in sorted((ROOT / "libs").glob("*/CMakeLists.txt")):
        text = re.sub(r"#[^\n]*", "", cm.read_text())
        m = re.search(r"simp_add_library\(\s*NAME\s+(\w+)\s+TYPE\s+(\w+)(.*?)\)", text, re.S)
        if not m:
            continue
        deps_text = m.group(3).split("DEPS", 1)[1] if "DEPS" in m.group(3) else ""
        libs[m.group(1)] = {"shared": m.group(2) == "SHARED",
                            "deps": sorted(set(re.findall(r"simp::(\w+)", deps_text)) - {m.group(1)})}
    for name, lib in libs.items():
        unknown = [d for d in lib["deps"] if d not in libs]
        if unknown:
            sys.exit(f"structure_svg: libs/{name}/CMakeLists.txt: DEPS names unknown libraries {unknown}")
    return libs


def reachable(libs, start, skip_direct=None):
    """The libraries `start` uses directly or through others (not through its direct use of `skip_direct`)."""
    seen, todo = set(), [d for d in libs[start]["deps"] if d != skip_direct]
    while todo:
        n = todo.pop()
        if n not in seen:
            seen.add(n)
            todo += libs[n]["deps"]
    return seen


def check_includes(libs):
    """Every `#include <simp/X/...>` of a library's files names itself or a library its DEPS reach:
    the picture drawn from the DEPS is then also the picture of the includes."""
    wrong = []
    for name in sorted(libs):
        allowed = reachable(libs, name) | {name}
        for f in sorted((ROOT / "libs" / name).rglob("*")):
            if f.suffix in (".h", ".cpp"):
                for used in sorted(set(re.findall(r"#include\s*<simp/(\w+)/", f.read_text()))):
                    if used not in allowed:
                        wrong.append(f"{f.relative_to(ROOT)} includes simp/{used}/ but {name}'s DEPS do not reach {used}")
    if wrong:
        sys.exit("structure_svg:\n" + "\n".join(wrong))


def floors_of(libs):
    floor = {}
    def visit(name, path=()):
        if name in path:
            sys.exit("structure_svg: dependency cycle " + " -> ".join(path + (name,)))
        if name not in floor:
            floor[name] = 1 + max((visit(d, path + (name,)) for d in libs[name]["deps"]), default=0)
        return floor[name]
    for name in libs:
        visit(name)
    return floor


def reduced_edges(libs):
    return [(a, b) for a in sorted(libs) for b in libs[a]["deps"] if b not in reachable(libs, a, b)]


def layout(libs, floor, edges):
    rows = {}
    for name in sorted(libs):
        rows.setdefault(floor[name], []).append(name)
    top = max(rows)
    width = max(len(r) for r in rows.values()) * (BOX_W + GAP_X) - GAP_X + 2 * MARGIN
    pos = {}
    for f in range(1, top + 1):  # bottom floor first, each row ordered by its dependencies' places
        row = rows[f]
        if f > 1:
            def centre(n):
                xs = [pos[b][0] for a, b in edges if a == n]
                return sum(xs) / len(xs) if xs else width / 2
            row.sort(key=lambda n: (centre(n), n))
        x0 = (width - (len(row) * (BOX_W + GAP_X) - GAP_X)) / 2
        for i, n in enumerate(row):
            pos[n] = (x0 + i * (BOX_W + GAP_X) + BOX_W / 2, MARGIN + (top - f) * FLOOR_H + BOX_H / 2)
    return pos, width, MARGIN * 2 + (top - 1) * FLOOR_H + BOX_H + 18


def svg(libs, floor, edges):
    pos, width, height = layout(libs, floor, edges)
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width:.0f}" height="{height:.0f}" '
           f'font-family="DejaVu Sans, sans-serif" font-size="13">',
           '<defs><marker id="head" markerWidth="8" markerHeight="8" refX="7" refY="4" orient="auto">'
           '<path d="M0,0 L8,4 L0,8 z" fill="#555"/></marker></defs>',
           f'<rect width="{width:.0f}" height="{height:.0f}" fill="white"/>']
    for a, b in edges:
        (xa, ya), (xb, yb) = pos[a], pos[b]
        out.append(f'<line x1="{xa:.1f}" y1="{ya + BOX_H / 2:.1f}" x2="{xb:.1f}" y2="{yb - BOX_H / 2 - 2:.1f}" '
                   'stroke="#555" stroke-width="1.2" marker-end="url(#head)"/>')
    for n, (x, y) in sorted(pos.items()):
        fill = "#f6c28b" if libs[n]["shared"] else "#cfe0f3"
        out.append(f'<rect x="{x - BOX_W / 2:.1f}" y="{y - BOX_H / 2:.1f}" width="{BOX_W}" height="{BOX_H}" '
                   f'rx="5" fill="{fill}" stroke="#333"/>')
        out.append(f'<text x="{x:.1f}" y="{y + 4:.1f}" text-anchor="middle">{n}</text>')
    out.append(f'<text x="{MARGIN}" y="{height - 6:.0f}" font-size="11" fill="#333">libs/: {len(libs)} libraries '
               f'on {max(floor.values())} floors, {len(edges)} arrows (transitive reduction of the CMake DEPS); '
               'orange = shared plugin</text>')
    out.append("</svg>")
    return "\n".join(out) + "\n"


def main():
    libs = read_libraries()
    check_includes(libs)
    floor = floors_of(libs)
    text = svg(libs, floor, reduced_edges(libs))
    if "--check" in sys.argv[1:]:
        if not OUT.exists() or OUT.read_text() != text:
            sys.exit(f"structure_svg: {OUT} does not match libs/*/CMakeLists.txt; run python3 doc/tools/structure_svg.py")
        return
    OUT.write_text(text)
    for f in sorted(set(floor.values())):
        print(f"floor {f}: " + ", ".join(sorted(n for n in libs if floor[n] == f)))
    print(f"wrote {OUT.relative_to(ROOT)}")


if __name__ == "__main__":
    main()
