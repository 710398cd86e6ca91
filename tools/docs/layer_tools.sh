#!/bin/bash
# Shared by the docs' compositing scripts (sourced): lacrima EXR layers taken out, summed and shown
# with oiiotool alone. Needs $config (lacrima's OCIO config).

# EXR (3 channels, ACEScg) -> sRGB PNG through the ACES SDR view, as lacrima's previews.
toPng() {
  oiiotool --colorconfig "$config" "$1" --iscolorspace ACEScg --ociodisplay "sRGB - Display" "ACES 1.0 - SDR Video" \
    -d uint8 -o "$2"
}

# The layer LAYER (its .R/.G/.B) of FRAME as a 3-channel EXR OUT.
extractLayer() {
  oiiotool "$1" --ch "$2.R,$2.G,$2.B" --chnames R,G,B -o "$3"
}

# The sum of the EXRs PARTS... written to OUTDIR/recombined.exr, the beauty of FRAME to
# OUTDIR/beauty.exr, and oiiotool's statistics of their difference printed.
sumAgainstBeauty() {
  local frame=$1 dir=$2
  shift 2
  local adds=()
  for ((i = 1; i < $#; ++i)); do adds+=(--add); done
  oiiotool "$@" "${adds[@]}" -o "$dir/recombined.exr"
  oiiotool "$frame" --ch R,G,B -o "$dir/beauty.exr"
  oiiotool "$dir/recombined.exr" "$dir/beauty.exr" --diff || true
}
