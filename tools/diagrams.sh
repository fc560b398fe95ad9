#!/usr/bin/env bash
# Regenerates the README's diagrams (docs/diagrams/*.svg) with the gmr binary: rule schemes, a
# concrete rule with its kappa arcs, a rejected rule with the checker's diagnostics overlaid, and
# the cube G-map, subdivided meshes with positions. Colours per dimension: 0 black, 1 red, 2 blue,
# 3 green.
#
#   tools/diagrams.sh                   # builds gmr in build/ if needed
#   GMR_BIN=build-diag/tools/gmr tools/diagrams.sh   # use an existing binary
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
if [[ -z "${GMR_BIN:-}" ]]; then
  cmake -S "$root" -B "$root/build" >/dev/null
  cmake --build "$root/build" --target gmr -j"$(nproc)" >/dev/null
  GMR_BIN="$root/build/tools/gmr"
fi
out=docs/diagrams
mkdir -p "$out"
run() { echo "gmr $*"; "$GMR_BIN" "$@"; }

# Rule schemes: labels "n0 <_,1,2>", hooks double-bordered, explicit arcs coloured per dimension.
run dot tools/data/rules/quad_subdivision.json -o "$out/quad_subdivision.svg"
run dot tools/data/rules/sew2.json -o "$out/sew2.svg"
run dot tools/data/rules/vertex_insertion.json -o "$out/vertex_insertion.svg"
# A concrete rule (2-sew, thesis Fig. 3.19a) with the kappa arcs of its joint representation.
run dot --kappa checker/tests/data/F5_fig319a_sew.json -o "$out/sew_concrete_kappa.svg"
# A rule the checker rejects (thesis Ex. 34): offending nodes filled, diagnostic codes as labels.
run dot --check checker/tests/data/F1_ex34_weak_incident.json -o "$out/rejected_ex34.svg"
# The cube as a 2-G-map (48 darts).
run dot tools/data/cube.off -o "$out/cube.svg"
# A rule scheme inferred by topological folding from the cube and its quad subdivision.
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
run convert tools/data/cube.off "$tmp/cube.json"
run apply tools/data/rules/quad_subdivision.json "$tmp/cube.json" --hook 0 -o "$tmp/sub.json"
run infer "$tmp/cube.json" "$tmp/sub.json" --orbit "<0,1,2>" -o "$tmp/inferred"
run dot "$tmp/inferred/rule_0.json" -o "$out/inferred_quad_subdivision.svg"
# Subdivision with positions (docs/embeddings.md): three iterations of each scheme, rendered by
# tools/render_mesh.py.
subdivide() {  # rule mesh.off out.off
  cp "$2" "$tmp/s0.off"
  for k in 1 2 3; do run apply "tools/data/rules/$1" "$tmp/s$((k - 1)).off" --all -o "$tmp/s$k.off" >/dev/null; done
  cp "$tmp/s3.off" "$3"
}
subdivide quad_subdivision.json tools/data/cube.off "$tmp/cc.off"
subdivide loop_subdivision.json tools/data/tetrahedron.off "$tmp/loop.off"
subdivide sqrt3_subdivision.json tools/data/octahedron.off "$tmp/sqrt3.off"
subdivide doo_sabin_subdivision.json tools/data/cube.off "$tmp/ds.off"
python3 tools/render_mesh.py "$out/subdivisions.svg" "Catmull-Clark (cube):$tmp/cc.off" \
  "Loop (tetrahedron):$tmp/loop.off" "sqrt(3) (octahedron):$tmp/sqrt3.off" "Doo-Sabin (cube):$tmp/ds.off"
