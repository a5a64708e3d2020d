/* hud_quality.c: hud_ortho.c's frame, translated with --quality 4 (issue
 * 27): below quality 6 POV-Ray computes no image map, and the overlay's
 * turned the whole frame black. */
#include "hud_ortho.c"
