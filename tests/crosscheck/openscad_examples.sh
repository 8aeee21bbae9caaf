#!/bin/bash
# Issue 14's examples count: every .scad that Debian's openscad installs under
# /usr/share/openscad/examples is exported to .csg by openscad (with the files it imports copied
# beside it), then meshed by `solidkit mesh X.csg --resolution 96 --facets openscad`; a model
# counts as meshed when solidkit exits 0 with a closed, manifold mesh.
# Usage: tests/crosscheck/openscad_examples.sh SOLIDKIT_BINARY [WORK_DIR]
set -u
BIN=$1
WORK=${2:-$(mktemp -d)}
EX=/usr/share/openscad/examples
mkdir -p "$WORK/csg" "$WORK/out"
find "$EX" -type f ! -name '*.scad' ! -name '*.json' -exec cp {} "$WORK/csg/" \;
ok=0; fail=0
for f in $(find "$EX" -name '*.scad' | sort); do
  rel=${f#$EX/}; n=$(echo "${rel%.scad}" | tr '/' '_')
  (cd "$(dirname "$f")" && timeout 120 openscad -o "$WORK/csg/$n.csg" "$f" >/dev/null 2>&1) || { echo "EXPORT-FAIL $n"; continue; }
  timeout 300 "$BIN" mesh "$WORK/csg/$n.csg" --resolution 96 --facets openscad --json --no-progress \
    >"$WORK/out/$n.json" 2>"$WORK/out/$n.err"
  rc=$?
  closed=$(python3 -c "import json; r=json.load(open('$WORK/out/$n.json')); print(int(r['boundary_edges']==0 and r['non_manifold_edges']==0))" 2>/dev/null || echo 0)
  if [ $rc = 0 ] && [ "$closed" = 1 ]; then ok=$((ok+1)); st=OK; else fail=$((fail+1)); st=FAIL; fi
  echo "$st $n $(head -c 200 "$WORK/out/$n.err" | tr '\n' ' ')"
done
echo "meshed=$ok failed=$fail"
