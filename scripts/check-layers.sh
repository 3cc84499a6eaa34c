#!/usr/bin/env bash
# Fails when a header or source includes a folder of a higher layer: the
# folders of include/featloc and src, lowest first, as the data flow reads
# (doc/architecture.md). A folder may include itself and anything below it.
# Run by ctest (test "Layers.IncludesPointDown").
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
LAYERS=(core config math io scan features matchers stereo odometry ekf estimators localization plot eval output pipeline live sim app gui)
rank() { local i; for i in "${!LAYERS[@]}"; do [ "${LAYERS[$i]}" = "$1" ] && { echo "$i"; return; }; done; echo -1; }
bad=0
while IFS= read -r f; do
  from=$(echo "$f" | sed -E 's#^(include/featloc|src)/([^/]+)/.*#\2#')
  rf=$(rank "$from")
  if [ "$rf" -lt 0 ]; then echo "$f: folder '$from' is not in the layer list of $0"; bad=1; continue; fi
  while IFS= read -r to; do
    rt=$(rank "$to")
    if [ "$rt" -lt 0 ] || [ "$rt" -gt "$rf" ]; then
      echo "$f includes featloc/$to/ (layer '$to' is above '$from')"; bad=1
    fi
  done < <(sed -n -E 's#^\#include "featloc/([a-z]+)/.*#\1#p' "$ROOT/$f" | sort -u)
done < <(cd "$ROOT" && { find include/featloc -mindepth 2 -name '*.h'; find src -mindepth 2 -name '*.cpp'; })
[ "$bad" = 0 ] && echo "layers: every include points down (${LAYERS[*]})"
exit "$bad"
