#!/bin/bash
# The light groups of a lacrima EXR recombined and regraded with oiiotool alone, for
# docs/compositing.md: the groups' sum against the beauty (the difference's statistics), the key
# group alone, and the frame with the key dimmed on the skin only (the key group times the
# CryptoMaterial matte of `skin`, taken off the beauty), each as an sRGB PNG through lacrima's OCIO
# config (ACEScg to the ACES SDR view, as lacrima's previews).
#
#   tools/docs/light_group_regrade.sh frame.exr OUTDIR [KEY_GROUP [DIM [MATERIAL...]]]
#
# Needs the frame rendered with "aovs": ["lightGroups", "CryptoMaterial"]; DIM (default 0.6) is the
# fraction of the key taken off the MATERIALs (default: skin and skin/wet, the skin under the tear's
# film).
set -euo pipefail
if [ $# -lt 2 ]; then
  echo "usage: $0 FRAME.exr OUTDIR [KEY_GROUP] [DIM]" >&2
  exit 2
fi
frame=$1 out=$2 key=${3:-key} dim=${4:-0.6}
shift $(($# < 4 ? $# : 4))
materials=("$@")
[ ${#materials[@]} -gt 0 ] || materials=(skin skin/wet)
here=$(cd "$(dirname "$0")" && pwd)
config="$here/../../scenes/ocio/config.ocio"
lacrima=${LACRIMA:-lacrima}
mkdir -p "$out"
source "$here/layer_tools.sh"
groups=$(oiiotool --info -v "$frame" | tr ',' '\n' | sed -n 's/^ *\(lightgroup_[^.]*\)\.R.*/\1/p' | sort -u)
if [ -z "$groups" ]; then
  echo "$0: $frame has no light group layers (render it with \"aovs\": [\"lightGroups\"])" >&2
  exit 1
fi
parts=()
for g in $groups; do
  extractLayer "$frame" "$g" "$out/$g.exr"
  parts+=("$out/$g.exr")
done
echo "the groups ($groups) summed against the beauty:"
sumAgainstBeauty "$frame" "$out" "${parts[@]}"
LACRIMA="$lacrima" "$here/cryptomatte_matte.sh" "$frame" CryptoMaterial "$out/matte.exr" "${materials[@]}" >/dev/null
oiiotool "$out/beauty.exr" "$out/lightgroup_$key.exr" "$out/matte.exr" --ch 0,0,0 --chnames R,G,B --mul \
  --mulc "$dim" --sub -o "$out/regraded.exr"
toPng "$out/beauty.exr" "$out/beauty.png"
toPng "$out/lightgroup_$key.exr" "$out/$key.png"
toPng "$out/regraded.exr" "$out/regraded.png"
echo "$out: beauty.png, $key.png (the $key group alone), regraded.png (the $key dimmed by $dim on ${materials[*]})"
