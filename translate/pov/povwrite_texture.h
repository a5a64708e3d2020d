/* povwrite_texture.h: the POV-Ray writer's texture images (issue 5):
 * which image file a textured mesh maps, how its uv coordinates map into
 * it, and the pigment that samples it. Private to the writer (povwrite.c).
 */
#ifndef RGL_POVWRITE_TEXTURE_H
#define RGL_POVWRITE_TEXTURE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "outbuf.h"
#include "povwrite_vgrid.h"
#include "scene.h"

/* An image file the scene refers to: RGBA texels, bottom row first, named
 * by its content (POVTEX_NAME_MAX with the NUL). The files go in the
 * output folder's POVTEX_DIR, apart from the frames' PNGs. */
#define POVTEX_NAME_MAX 32
#define POVTEX_DIR "textures"
typedef struct povtex_image {
    char name[POVTEX_NAME_MAX];
    uint8_t *rgba;
    int width, height;
    bool alpha; /* some texel is not opaque: the file keeps the alpha channel */
    /* what it was made from, to reuse it within the frame */
    int32_t texture;
    int32_t lo[2], hi[2]; /* tile range of each clamped axis; 0, 1 otherwise */
    bool keep_alpha;
    uint8_t tint[3]; /* what the texels' colour was multiplied by (/255) */
    bool declared[2]; /* its pigment (nearest, linear) declared in the frame (povtex_declared) */
} povtex_image;

typedef struct povtex {
    povtex_image *imgs;
    size_t n, cap;
    bool quick; /* image pigments carry quick_color, their mean (scene.options.quality below 6) */
} povtex;

void povtex_reset(povtex *pt);
void povtex_finish(povtex *pt);

/* How uv coordinates of a mesh map into the image of texture t: for a
 * clamped axis the file holds the texture with its edge texels repeated
 * over the tiles the coordinates [uvlo, uvhi] reach (POV-Ray's image_map
 * only repeats), and u' = u * scale + offset. Returns the image's index
 * in pt, or -1 when memory ran out. keep_alpha: the file keeps the
 * texels' alpha (when some is below 1), which POV-Ray reads as transmit.
 * tint (NULL: none): the texels' colour is multiplied by it per channel
 * (0..1), GL_MODULATE's product with a coloured material made in the image
 * (docs/mapping.md section 24). With the texture's alpha test
 * (alpha_func), texels whose alpha (times alpha_af when alpha_uses_af)
 * fails are made fully transparent, the others keep their alpha
 * (keep_alpha) or become opaque. */
int povtex_map(povtex *pt, const scene *s, int32_t t, const float uvlo[2], const float uvhi[2],
               bool keep_alpha, const float tint[3], float scale[2], float offset[2]);

/* The text inside pigment{ } that samples image i of pt as GL samples
 * texture t: `uv_mapping image_map{png "NAME" gamma 2.2 interpolate 2}`,
 * with pt->quick ` quick_color rgb<mean>` after it.
 * Returns the number of bytes (< POVTEX_PIGMENT_MAX) written to buf. */
#define POVTEX_PIGMENT_MAX 192
size_t povtex_pigment(const povtex *pt, size_t i, const scene_texture *t,
                      char buf[POVTEX_PIGMENT_MAX]);

/* The alpha test of texture t on its filtered alpha (scene_alpha_crisp):
 * declares (before the mesh) a function rgl_at<id> of t's image with its
 * alpha, and puts into buf a pigment of image img (the colours) where the
 * filtered alpha passes and fully transparent elsewhere, an edge as crisp
 * as GL's per-fragment test. Returns 0, or -1 when memory ran out or buf
 * is too small. */
int povtex_alpha_pigment(outbuf *ob, povtex *pt, const scene *s, int32_t t, size_t img,
                         const float uvlo[2], const float uvhi[2], unsigned id, char *buf,
                         size_t cap);

/* The same for an image that is not a GL texture (filtering linear or
 * nearest). */
size_t povtex_image_pigment(const povtex *pt, size_t i, bool linear,
                            char buf[POVTEX_PIGMENT_MAX]);

/* The name of a pigment declared once in the frame's SDL that samples
 * image i (as povtex_image_pigment, without the uv_mapping): declared into
 * ob, ahead of its first use, on the first call. POV-Ray reads an
 * image_map's file again at every occurrence, so a pigment_map of levels
 * per mesh (povmip_pigment) names them instead. Returns the name's length,
 * 0 when it does not fit. */
#define POVTEX_DECLARED_MAX 40
size_t povtex_declared(outbuf *ob, povtex *pt, size_t i, bool linear,
                       char name[POVTEX_DECLARED_MAX]);

/* Adds a copy of the cw x ch box at (x0, y0) of the frame's image of
 * bitmaps and pixel rectangles (scene.overlay: RGBA rows of w pixels,
 * bottom row first; its alpha kept, 0 where nothing was drawn). Returns
 * its index in pt, -1 when memory ran out. */
int povtex_overlay(povtex *pt, const uint8_t *rgba, int w, int x0, int y0, int cw, int ch);

/* Vertex colours as one image (docs/mapping.md section 9): per face a
 * 2 x 2 texel block A, B, C, D = B + C - A, which bilinear filtering turns
 * into GL's linear interpolation of the corners' colours. A face's corners
 * c[0..2] are opaque RGB colours; the corner at A is chosen so that D
 * needs the least clamping to 0..255 (8-bit texels).
 *
 * povtex_colour_origin: that corner (0..2), or -1 when even the best
 * clamps D by more than POVTEX_CLAMP_MAX (in 1/255; the error inside the
 * face is at most a quarter of it, at the middle of the edge B-C). */
#define POVTEX_CLAMP_MAX 4
int povtex_colour_origin(const float *const c[3]);
/* A colour channel (0..1) as an 8-bit texel value, NaN as 0. */
static inline uint8_t povtex_quantise(float x)
{
    return (uint8_t)(x > 0 ? (x < 1 ? (int)(x * 255.0f + 0.5f) : 255) : 0);
}
/* How far D = B + C - A leaves 0..255, worst channel. */
static inline int povtex_excess_q(const uint8_t a[3], const uint8_t b[3], const uint8_t c[3])
{
    int worst = 0;
    for (int k = 0; k < 3; k++) {
        int d = b[k] + c[k] - a[k];
        int e = d < 0 ? -d : d > 255 ? d - 255 : 0;
        worst = e > worst ? e : worst;
    }
    return worst;
}
/* povtex_colour_origin from the corners as povtex_quantise gives them
 * (inline: called for every face of a mesh with vertex colours). */
static inline int povtex_colour_origin_q(uint8_t q[3][3])
{
    int be = povtex_excess_q(q[0], q[1], q[2]), best = 0;
    if (be > 0) {
        int e = povtex_excess_q(q[1], q[2], q[0]);
        if (e < be)
            best = 1, be = e;
    }
    if (be > 0) {
        int e = povtex_excess_q(q[2], q[0], q[1]);
        if (e < be)
            best = 2, be = e;
    }
    return be <= POVTEX_CLAMP_MAX ? best : -1;
}

/* Adds the image of n faces, corners[3 * j + k] the colour of corner k of
 * face j, and writes the uv of each corner (its texel's centre) to
 * uv[6 * j + 2 * k]. Returns the image's index in pt, -1 when memory ran
 * out. Images are marked texture -1. */
int povtex_colours(povtex *pt, const float *const *corners, size_t n, float *uv);

/* The same with a grid (povgrid_build over nv vertices, whose colours
 * it took as g->qc): its texels first, one per vertex on a cell, whose uv goes to
 * vuv[2 * v] (0, 0 for vertices on no cell), then the blocks of the n
 * faces off the grid as povtex_colours places them. Returns the image's
 * index, -1 when memory ran out, POVTEX_TOO_LARGE when the image would
 * pass POV-Ray's image size (then povtex_colours alone fits). */
#define POVTEX_TOO_LARGE (-2)
int povtex_colour_grid(povtex *pt, const povgrid *g, size_t nv, float *vuv,
                       const float *const *corners, size_t n, float *uv);

#endif
