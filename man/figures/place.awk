# place.awk: fromcad's cubic of potrace's trace (millimetres, from an
# SVG of W by H pt) back in the points' units: pixel PX wide, the
# raster's lower left at X0, Y0 (as raster.awk puts it).
BEGIN { k = 25.4 / 72; s = PX / k }
/^[-0-9.]/ { printf "%.6g %.6g %.6g %.6g %.6g %.6g %.6g %.6g\n",
	X0 + s * $1, Y0 + PX * H + s * $2, X0 + s * $3, Y0 + PX * H + s * $4,
	s * $5, s * $6, s * $7, s * $8; next }
{ print }
