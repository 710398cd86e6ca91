#!/bin/bash
# A Cryptomatte matte of one or more names from a lacrima EXR, with oiiotool alone, for
# docs/compositing.md: per rank, the coverage where the rank's ID is one of the names', summed over
# the ranks (the keyer's work, as the Cryptomatte specification describes it).
#
#   tools/docs/cryptomatte_matte.sh frame.exr CryptoMaterial matte.exr tear skin/wet
#
# The names' IDs are read from the EXR's manifest (lacrima info lists it).
set -euo pipefail
if [ $# -lt 4 ]; then
  echo "usage: $0 FRAME.exr CryptoObject|CryptoMaterial OUT.exr NAME [NAME...]" >&2
  exit 2
fi
frame=$1 type=$2 out=$3
shift 3
names=("$@")
lacrima=${LACRIMA:-lacrima}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
parts=()
for name in "${names[@]}"; do
  hex=$("$lacrima" info "$frame" | awk -v type="$type" -v name="$name" '
    /^  Cryptomatte / { inside = ($2 == type) ; next }
    inside && $1 == name && NF == 2 { print $2; exit }')
  if [ -z "$hex" ]; then
    echo "$0: $frame has no '$name' in its $type manifest" >&2
    exit 1
  fi
  # The ID as a float (its bits are the manifest's 8 hex digits).
  id=$(python3 -c "import struct,sys; print(repr(struct.unpack('>f', bytes.fromhex(sys.argv[1]))[0]))" "$hex")
  for layer in 00 01 02; do
    for pair in "R G" "B A"; do
      read -r idChannel coverageChannel <<< "$pair"
      # 1 where the ID is the name's (any other ID differs by far more than 1e-30 of it), else 0.
      oiiotool "$frame" --ch "$type$layer.$idChannel" --subc "$id" --abs --mulc 1e30 --clamp:min=0:max=1 \
        --mulc -1 --addc 1 "$frame" --ch "$type$layer.$coverageChannel" --mul -o "$tmp/part${#parts[@]}.exr"
      parts+=("$tmp/part${#parts[@]}.exr")
    done
  done
  echo "$name: ID $hex"
done
adds=()
for ((i = 1; i < ${#parts[@]}; ++i)); do adds+=(--add); done
oiiotool "${parts[@]}" "${adds[@]}" --chnames Y -o "$out"
echo "$out: the $type matte of ${names[*]}"
