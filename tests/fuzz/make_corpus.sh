#!/usr/bin/env bash
# Rebuilds the committed seed corpus corpus/TARGET/ from the tests' own inputs:
#   the malformed-input matrix (tests/data/malformed, files up to 16 KiB), the bundled straight
#   tube, small yarns made by `towgeom generate` (needs build/towgeom) and one file using every
#   variant of the format the reader tests cover (BOM, CRLF, commas, tabs, comments inside a
#   section, closing points, '+' signs, an underflowing coordinate).
# Run by hand after adding test inputs; run_fuzzers.sh only reads the corpus.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../.." && pwd)
cli=${TOWGEOM_CLI:-$root/build/towgeom}
seeds=$(mktemp -d)
trap 'rm -rf "$seeds"' EXIT

for f in "$root"/tests/data/malformed/*.stw "$root"/examples/data/straight_tube.stw; do
  [[ -f "$f" && $(stat -c %s "$f") -le 16384 ]] && cp "$f" "$seeds/"
done
for weave in "plain --section ellipse" "twill --section hermite --overlap 0.1" "orthogonal --section racetrack"; do
  name=${weave%% *}
  # shellcheck disable=SC2086
  "$cli" generate --weave $weave --sections 6 --points 8 --out "$seeds/$name" --quiet >/dev/null
  for f in "$seeds/$name"/{warp_0,binder_0}.stw; do [[ -f "$f" ]] && mv "$f" "$seeds/${name}_$(basename "$f")"; done
  rm -r "${seeds:?}/$name"
done
{
  printf '\xef\xbb\xbf# every variant of the format\r\ntow variants # named\r\n'
  for i in 0 1 2 3; do
    ((i)) && printf '\r\n\r\n'
    printf '# section %d\r\n' "$i"
    printf '%d\t1\t0\r\n%d, 0.5, 0.8660254037844386\r\n%d -0.5 +0.8660254037844386\r\n' "$i" "$i" "$i"
    printf '# between points\r\n'
    printf '%d -1 1e-400\r\n%d,-0.5,-0.8660254037844386\r\n%d 0.5 -0.8660254037844386\r\n%d 1 0\r\n' "$i" "$i" "$i" "$i"
  done
} > "$seeds/variants.stw"

for target in stack_reader stack_fit; do
  rm -rf "${here:?}/corpus/$target"
  mkdir -p "$here/corpus/$target"
  cp "$seeds"/* "$here/corpus/$target/"
done
echo "make_corpus: $(find "$here/corpus/stack_reader" -type f | wc -l) seeds per target" >&2
