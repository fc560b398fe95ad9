#!/usr/bin/env bash
# Regenerates docs/architecture.svg: the module graph of the gmr libraries and the gmr binary, read
# from CMake (`cmake --graphviz`) and laid out by Graphviz's dot. Tests, proofs, fuzz targets,
# condition plug-ins, benchmarks, layering checks and
# third-party targets are left out; an arrow A -> B means "A links B" (A may use B).
# Usage: tools/architecture.sh [build dir, default build/]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$root/build}"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
(cd "$tmp" && cmake --graphviz="$tmp/all.dot" "$build" >/dev/null)
python3 - "$tmp/all.dot" "$tmp/modules.dot" <<'PY'
import re, sys
src, out = sys.argv[1], sys.argv[2]
text = open(src).read()
label = dict(re.findall(r'"(node\d+)" \[ label = "([^"]+)"', text))
def keep(name):
    return (name == "gmr" or name.startswith("gmr_")) and not re.search(
        r"_test$|_layering$|_cgal_test$|_slow_test$|^gmr_warnings$|^gmr_proptest|^gmr_fuzz_|^gmr_proofs|^gmr_plugin|^gmr_bench", name)
edges = set()
for a, b in re.findall(r'"(node\d+)" -> "(node\d+)"', text):
    if keep(label[a]) and keep(label[b]):
        edges.add((label[a], label[b]))
# gmr_model is an interface bundle of the model libraries: draw the edges to its members instead.
bundle = {b for a, b in edges if a == "gmr_model"}
edges = {(a, m) for a, b in edges if b == "gmr_model" for m in bundle} | {
    (a, b) for a, b in edges if "gmr_model" not in (a, b)}
nodes = sorted({x for e in edges for x in e})
with open(out, "w") as f:
    f.write('digraph modules {\n  rankdir=BT;\n  node [shape=box, style=rounded, fontname="Helvetica"];\n')
    for n in nodes:
        f.write(f'  "{n}";\n')
    for a, b in sorted(edges):
        f.write(f'  "{a}" -> "{b}";\n')
    f.write("}\n")
PY
# Transitive reduction (tred): only the direct layering is drawn.
tred "$tmp/modules.dot" > "$tmp/reduced.dot"
dot -Tsvg "$tmp/reduced.dot" -o "$root/docs/architecture.svg"
cp "$tmp/reduced.dot" "$root/docs/architecture.dot"
echo "wrote docs/architecture.svg"
