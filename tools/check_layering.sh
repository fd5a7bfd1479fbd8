#!/usr/bin/env bash
# The include graph runs one way: physics headers (include/blaze) -> kernels/ -> pipeline/ ->
# programs (apps, studies, bench, verification). A header that includes a later layer fails here.
set -u
cd "$(dirname "$0")/.."
bad=0
check() {  # layer folder, forbidden include prefixes...
  local dir=$1; shift
  for p in "$@"; do
    if grep -rn "#include \"$p" "$dir" --include='*.hpp' --include='*.cpp'; then bad=1; fi
  done
}
check include/blaze kernels/ pipeline/
check kernels pipeline/
if [ $bad -ne 0 ]; then echo "layering: the includes above run against physics -> kernels -> pipeline" >&2; exit 1; fi
echo "layering: physics -> kernels -> pipeline holds"
