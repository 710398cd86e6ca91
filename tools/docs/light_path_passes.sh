#!/bin/bash
# The light-path passes of a lacrima EXR recombined and regraded with oiiotool alone, for
# docs/compositing.md: the passes' sum against the beauty (the difference's statistics), a 3 x 3
# contact sheet of the passes, and the frame with the tear's specular glints lifted (the
# specular_direct pass times the CryptoMaterial matte of the tear, times GAIN - 1, added to the
# beauty), each as an sRGB PNG through lacrima's OCIO config (ACEScg to the ACES SDR view, as
# lacrima's previews).
#
#   tools/docs/light_path_passes.sh frame.exr OUTDIR [GAIN [MATERIAL...]]
#
# Needs the frame rendered with "aovs": ["lightPaths", "CryptoMaterial"]; GAIN (default 2) scales
# the glints of the MATERIALs (default: tear).
set -euo pipefail
if [ $# -lt 2 ]; then
  echo "usage: $0 FRAME.exr OUTDIR [GAIN [MATERIAL...]]" >&2
  exit 2
fi
frame=$1 out=$2 gain=${3:-2}
shift $(($# < 3 ? $# : 3))
materials=("$@")
[ ${#materials[@]} -gt 0 ] || materials=(tear)
here=$(cd "$(dirname "$0")" && pwd)
config="$here/../../scenes/ocio/config.ocio"
lacrima=${LACRIMA:-lacrima}
mkdir -p "$out"
source "$here/layer_tools.sh"
passes=(diffuse_direct diffuse_indirect specular_direct specular_indirect transmission_direct transmission_indirect
  subsurface emission environment)
channels=$(oiiotool --info -v "$frame")
parts=()
for p in "${passes[@]}"; do
  if ! grep -q "$p\.R" <<<"$channels"; then
    echo "$0: $frame has no $p layer (render it with \"aovs\": [\"lightPaths\"])" >&2
    exit 1
  fi
  extractLayer "$frame" "$p" "$out/$p.exr"
  parts+=("$out/$p.exr")
done
echo "the nine passes summed against the beauty:"
sumAgainstBeauty "$frame" "$out" "${parts[@]}"
pngs=()
for p in "${passes[@]}"; do
  toPng "$out/$p.exr" "$out/$p.png"
  pngs+=("$out/$p.png")
done
oiiotool "${pngs[@]}" --mosaic:pad=4 3x3 -o "$out/passes.png"
LACRIMA="$lacrima" "$here/cryptomatte_matte.sh" "$frame" CryptoMaterial "$out/matte.exr" "${materials[@]}" >/dev/null
oiiotool "$out/beauty.exr" "$out/specular_direct.exr" "$out/matte.exr" --ch 0,0,0 --chnames R,G,B --mul \
  --mulc "$(awk "BEGIN { print $gain - 1 }")" --add -o "$out/glints.exr"
toPng "$out/beauty.exr" "$out/beauty.png"
toPng "$out/glints.exr" "$out/glints.png"
echo "$out: passes.png (in reading order: ${passes[*]}),"
echo "  beauty.png, glints.png (the specular_direct glints of ${materials[*]} times $gain)"
