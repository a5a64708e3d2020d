/* interp_texslice.c: images derived from a texture's for what POV-Ray's
 * image_map cannot sample itself: a mirror-clamped texture (the image
 * beside its mirror image) and the slice of a 3D texture that a primitive
 * of constant r shows (interp_texture.c decides when).
 */
#include <math.h>
#include <string.h>

#include "interp_internal.h"
#include "interp_teximage.h"
#include "talloc.h"

void interp_tex_mirror_fill(uint8_t *out, const tex_image *img, bool ms, bool mt)
{
    size_t w = (size_t)img->width, h = (size_t)img->height;
    size_t ow = w * (ms ? 2 : 1), oh = h * (mt ? 2 : 1);
    for (size_t y = 0; y < oh; y++) {
        size_t sy = mt ? (y < h ? h - 1 - y : y - h) : y;
        for (size_t x = 0; x < ow; x++) {
            size_t sx = ms ? (x < w ? w - 1 - x : x - w) : x;
            memcpy(out + (y * ow + x) * 4, img->rgba + (sy * w + sx) * 4, 4);
        }
    }
}

/* Texel index i of n along a coordinate, wrapped as GL wraps it (GL 2.1
 * 3.8.7); the clamping modes all clamp to the edge texels here. */
static int wrap_index(int64_t i, int n, GLenum wrap)
{
    if (wrap == GL_REPEAT) {
        i %= n;
        return (int)(i < 0 ? i + n : i);
    }
    if (wrap == GL_MIRRORED_REPEAT) {
        int64_t p = i % (2 * (int64_t)n);
        if (p < 0)
            p += 2 * (int64_t)n;
        return (int)(p < n ? p : 2 * (int64_t)n - 1 - p);
    }
    if (interp_mirror_clamp(wrap) && i < 0)
        i = -1 - i;
    return (int)(i < 0 ? 0 : i >= n ? n - 1 : i);
}

tex_image *interp_tex_slice(const tex_image *src, int depth, double r, bool linear,
                            GLenum wrap_r)
{
    int w = src->width, h = src->height / depth;
    double z = fmin(fmax(r * depth, -1e9), 1e9); /* far outside: any far index */
    int64_t k0;
    float f = 0;
    if (linear) {
        double fl = floor(z - 0.5);
        k0 = (int64_t)fl;
        f = (float)(z - 0.5 - fl);
    } else {
        k0 = (int64_t)floor(z);
    }
    int s0 = wrap_index(k0, depth, wrap_r), s1 = wrap_index(k0 + 1, depth, wrap_r);
    size_t n = (size_t)w * (size_t)h * 4;
    tex_image *img = tr_realloc(NULL, sizeof *img + n);
    if (!img)
        return NULL;
    img->refs = 1;
    img->width = w;
    img->height = h;
    const uint8_t *a = src->rgba + (size_t)s0 * n, *b = src->rgba + (size_t)s1 * n;
    for (size_t i = 0; i < n; i++)
        img->rgba[i] = (uint8_t)(a[i] + f * ((float)b[i] - (float)a[i]) + 0.5f);
    img->serial = 0;
    return img;
}
