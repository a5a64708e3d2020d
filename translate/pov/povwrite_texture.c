/* povwrite_texture.c: texture images of the POV-Ray writer (issue 5,
 * docs/mapping.md "Textures").
 *
 * POV-Ray's image_map repeats the image or (`once`) shows nothing outside
 * it; GL's clamp modes repeat the edge texels. A clamped axis is therefore
 * written as a wider image: the texture's tiles that the mesh's
 * coordinates reach, each filled with edge texels, plus one texel of edge
 * on either side so that bilinear filtering at the border does not wrap.
 * Coordinates are then remapped into it. Files are named by a hash of
 * their content, so the same image is one file however many frames and
 * meshes use it.
 */
#include "povwrite_texture.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "numfmt.h"
#include "talloc.h"

static float clamp01(float x) { return x > 0 ? (x < 1 ? x : 1) : 0; /* NaN: 0 */ }

/* A clamped axis spans at most this many tiles; coordinates further out
 * are clamped to it (the texture's edge shows there anyway). */
#define CLAMP_TILES_MAX 16
/* ... and the padded image at most this many texels per side. */
#define PADDED_MAX 16384

void povtex_reset(povtex *pt)
{
    for (size_t i = 0; i < pt->n; i++)
        tr_free(pt->imgs[i].rgba);
    pt->n = 0;
}

void povtex_finish(povtex *pt)
{
    povtex_reset(pt);
    tr_free(pt->imgs);
    pt->imgs = NULL;
    pt->cap = 0;
}

static uint64_t content_hash(const uint8_t *rgba, int w, int h, bool alpha)
{
    uint64_t x = 0xcbf29ce484222325ull; /* FNV-1a */
    uint32_t head[3] = {(uint32_t)w, (uint32_t)h, alpha};
    const uint8_t *b = (const uint8_t *)head;
    for (size_t i = 0; i < sizeof head; i++)
        x = (x ^ b[i]) * 0x100000001b3ull;
    size_t n = (size_t)w * (size_t)h * 4;
    for (size_t i = 0; i < n; i++)
        x = (x ^ rgba[i]) * 0x100000001b3ull;
    return x;
}

/* The tile range [lo, hi) of coordinates [a, b], at least [0, 1). */
static void tiles(float a, float b, int32_t *lo, int32_t *hi)
{
    double l = isfinite(a) ? floor(a) : 0, h = isfinite(b) ? ceil(b) : 1;
    l = l < 0 ? l : 0;
    h = h > 1 ? h : 1;
    if (l < -CLAMP_TILES_MAX / 2)
        l = -CLAMP_TILES_MAX / 2;
    if (h > CLAMP_TILES_MAX / 2 + 1)
        h = CLAMP_TILES_MAX / 2 + 1;
    *lo = (int32_t)l;
    *hi = (int32_t)h;
}

/* One axis of the image written: which texels of the texture file texel
 * j takes (-1: the border colour) and their weights. */
typedef struct axis_tap {
    int64_t i[2];
    double w[2];
    int n;
    bool out; /* outside the texture (a clamped axis' padding) */
} axis_tap;

/* GL_CLAMP under GL_LINEAR (GL 2.1 3.8.7, 3.8.8): the coordinate clamped to
 * [0, 1], then the two texels about it, those past the edge the border
 * colour. Over u the result is piecewise linear with knots at the texel
 * centres and at the edges 0 and 1, half a texel from the first and last
 * centres; so the image is written at twice the resolution, a sample of
 * GL's filter every half texel with the edges on samples, and POV-Ray's
 * bilinear filter between the samples is GL's exactly. */
static axis_tap clamp_linear_tap(double u, int n)
{
    axis_tap t = {{0, 0}, {1, 0}, 2, u < 0 || u > 1};
    double uc = u < 0 ? 0 : u > 1 ? 1 : u, x = uc * n - 0.5, f = floor(x);
    t.i[0] = (int64_t)f;
    t.i[1] = t.i[0] + 1;
    t.w[1] = x - f;
    t.w[0] = 1 - t.w[1];
    for (int k = 0; k < 2; k++)
        if (t.i[k] < 0 || t.i[k] >= n)
            t.i[k] = -1;
    return t;
}

int povtex_map(povtex *pt, const scene *s, int32_t t, const float uvlo[2], const float uvhi[2],
               bool keep_alpha, const float tint[3], float scale[2], float offset[2])
{
    const scene_texture *tx = &s->textures[t];
    bool clamp[2] = {!tx->repeat_s, !tx->repeat_t};
    /* GL_MIRRORED_REPEAT: the file holds the texture and its mirror image,
     * a period of two tiles that image_map repeats. */
    bool mirror[2] = {tx->repeat_s && tx->mirror_s, tx->repeat_t && tx->mirror_t};
    /* GL_CLAMP, GL_LINEAR: at twice the resolution (clamp_linear_tap);
     * mipmaps keep one image per level, whose filter the level decides. */
    bool twice[2] = {clamp[0] && tx->linear && tx->border_s && !tx->to_border_s && !tx->mip_filter &&
                         !tx->cube,
                     clamp[1] && tx->linear && tx->border_t && !tx->to_border_t && !tx->mip_filter &&
                         !tx->cube};
    uint8_t tint8[3] = {255, 255, 255};
    if (tint)
        for (int k = 0; k < 3; k++)
            tint8[k] = (uint8_t)(clamp01(tint[k]) * 255.0f + 0.5f);
    int size[2] = {tx->width, tx->height};
    int32_t lo[2] = {0, 0}, hi[2] = {1, 1};
    int pad[2] = {0, 0}, out[2];
    for (int k = 0; k < 2; k++) {
        int per = twice[k] ? 2 : 1;
        if (clamp[k]) {
            tiles(uvlo[k], uvhi[k], &lo[k], &hi[k]);
            while ((int64_t)(hi[k] - lo[k]) * size[k] * per + 3 > PADDED_MAX && hi[k] - lo[k] > 1) {
                if (hi[k] > 1)
                    hi[k]--;
                else
                    lo[k]++;
            }
            pad[k] = 1;
        }
        if (twice[k]) {
            /* sample j at u = lo + (j - 1) / 2n, the file's texel centre
             * (j + 1/2) / out: one sample before lo, two past hi */
            out[k] = (hi[k] - lo[k]) * size[k] * 2 + 3;
            scale[k] = (float)(2.0 * size[k] / out[k]);
            offset[k] = (float)((1.5 - 2.0 * lo[k] * size[k]) / out[k]);
            continue;
        }
        out[k] = (hi[k] - lo[k]) * size[k] * (mirror[k] ? 2 : 1) + 2 * pad[k];
        /* texel x of the file is texel x - pad + lo * size of the texture */
        scale[k] = (float)((double)size[k] / out[k]);
        offset[k] = (float)(((double)pad[k] - (double)lo[k] * size[k]) / out[k]);
    }
    for (size_t i = 0; i < pt->n; i++) {
        const povtex_image *im = &pt->imgs[i];
        if (im->texture == t && im->keep_alpha == keep_alpha && im->lo[0] == lo[0] &&
            im->lo[1] == lo[1] &&
            im->hi[0] == hi[0] && im->hi[1] == hi[1] && memcmp(im->tint, tint8, 3) == 0)
            return (int)i;
    }
    if (tr_grow((void **)&pt->imgs, &pt->cap, pt->n + 1, sizeof *pt->imgs) != 0)
        return -1;
    size_t n = (size_t)out[0] * (size_t)out[1] * 4;
    uint8_t *px = tr_realloc(NULL, n);
    if (!px)
        return -1;
    /* Outside the texture the edge texel shows, as GL_CLAMP_TO_EDGE and
     * nearest filtering give; GL_CLAMP with GL_LINEAR clamps the
     * coordinate to the texture's edge, where the filter weighs the edge
     * texel and the border colour half and half (GL 1.5 3.8.7, Mesa): that
     * mix, per axis, outside, where the image is not written twice as
     * fine. GL_CLAMP_TO_BORDER takes the border colour for every texel
     * outside (GL 2.1 3.8.7), so the bilinear filter across the edge of
     * the padded image is GL's. */
    bool mix[2] = {tx->linear && tx->border_s && !tx->to_border_s && !twice[0],
                   tx->linear && tx->border_t && !tx->to_border_t && !twice[1]};
    bool to_border[2] = {tx->to_border_s, tx->to_border_t};
    uint8_t border[4];
    for (int k = 0; k < 4; k++)
        border[k] = (uint8_t)(tx->border[k] * 255.0f + 0.5f);
    bool alpha = false;
    for (int y = 0; y < out[1]; y++) {
        axis_tap ty = {{0, 0}, {1, 0}, 1, false};
        if (twice[1]) {
            ty = clamp_linear_tap(lo[1] + (y - 1) / (2.0 * size[1]), size[1]);
        } else {
            int64_t sy = (int64_t)y - pad[1] + (int64_t)lo[1] * size[1];
            ty.out = sy < 0 || sy >= size[1];
            if (clamp[1])
                sy = sy < 0 ? 0 : sy >= size[1] ? size[1] - 1 : sy;
            else if (mirror[1])
                sy = sy < size[1] ? sy : 2 * (int64_t)size[1] - 1 - sy;
            else
                sy = ((sy % size[1]) + size[1]) % size[1];
            ty.i[0] = to_border[1] && ty.out ? -1 : sy;
        }
        for (int x = 0; x < out[0]; x++) {
            axis_tap tx_ = {{0, 0}, {1, 0}, 1, false};
            if (twice[0]) {
                tx_ = clamp_linear_tap(lo[0] + (x - 1) / (2.0 * size[0]), size[0]);
            } else {
                int64_t sx = (int64_t)x - pad[0] + (int64_t)lo[0] * size[0];
                tx_.out = sx < 0 || sx >= size[0];
                if (clamp[0])
                    sx = sx < 0 ? 0 : sx >= size[0] ? size[0] - 1 : sx;
                else if (mirror[0])
                    sx = sx < size[0] ? sx : 2 * (int64_t)size[0] - 1 - sx;
                else
                    sx = ((sx % size[0]) + size[0]) % size[0];
                tx_.i[0] = to_border[0] && tx_.out ? -1 : sx;
            }
            uint8_t *d = px + ((size_t)y * (size_t)out[0] + (size_t)x) * 4;
            if (tx_.n == 1 && ty.n == 1) {
                memcpy(d, tx_.i[0] < 0 || ty.i[0] < 0
                              ? border
                              : tx->rgba + ((size_t)ty.i[0] * (size_t)size[0] + (size_t)tx_.i[0]) * 4,
                       4);
            } else {
                double acc[4] = {0, 0, 0, 0};
                for (int b = 0; b < ty.n; b++)
                    for (int a = 0; a < tx_.n; a++) {
                        double wt = tx_.w[a] * ty.w[b];
                        const uint8_t *src =
                            tx_.i[a] < 0 || ty.i[b] < 0
                                ? border
                                : tx->rgba + ((size_t)ty.i[b] * (size_t)size[0] + (size_t)tx_.i[a]) * 4;
                        for (int k = 0; k < 4; k++)
                            acc[k] += wt * src[k];
                    }
                for (int k = 0; k < 4; k++)
                    d[k] = (uint8_t)(acc[k] > 255 ? 255 : acc[k] + 0.5);
            }
            for (int k = 0; k < 3; k++) /* rounded product: 255 keeps the texel */
                d[k] = (uint8_t)((d[k] * tint8[k] + 127) / 255);
            for (int k = 0; k < 4; k++) {
                if (mix[0] && tx_.out)
                    d[k] = (uint8_t)((d[k] + border[k] + 1) / 2);
                if (mix[1] && ty.out)
                    d[k] = (uint8_t)((d[k] + border[k] + 1) / 2);
            }
            if (scene_alpha_crisp(tx)) {
                if (!keep_alpha) /* the test is the pigment's (povtex_alpha_pigment) */
                    d[3] = 255;
            } else if (tx->alpha_func) {
                /* GL discards the fragment: transmit 1, crisp under GL_NEAREST. */
                float fa = d[3] / 255.0f * (tx->alpha_uses_af ? tx->alpha_af : 1.0f);
                if (!scene_alpha_pass(tx->alpha_func, fa, tx->alpha_ref))
                    d[3] = 0;
                else if (!keep_alpha)
                    d[3] = 255;
            }
            alpha = alpha || d[3] != 255;
        }
    }
    povtex_image *im = &pt->imgs[pt->n++];
    memset(im, 0, sizeof *im);
    im->rgba = px;
    im->width = out[0];
    im->height = out[1];
    im->alpha = alpha && (keep_alpha || tx->alpha_func);
    im->keep_alpha = keep_alpha;
    im->texture = t;
    memcpy(im->lo, lo, sizeof lo);
    memcpy(im->hi, hi, sizeof hi);
    memcpy(im->tint, tint8, sizeof tint8);
    snprintf(im->name, sizeof im->name, "rgl-tex-%016llx.png",
             (unsigned long long)content_hash(px, out[0], out[1], im->alpha));
    return (int)(pt->n - 1);
}

int povtex_overlay(povtex *pt, const uint8_t *rgba, int stride, int x0, int y0, int w, int h)
{
    size_t n = (size_t)w * (size_t)h * 4;
    if (tr_grow((void **)&pt->imgs, &pt->cap, pt->n + 1, sizeof *pt->imgs) != 0)
        return -1;
    uint8_t *px = tr_realloc(NULL, n);
    if (!px)
        return -1;
    for (int y = 0; y < h; y++)
        memcpy(px + (size_t)y * (size_t)w * 4,
               rgba + ((size_t)(y0 + y) * (size_t)stride + (size_t)x0) * 4, (size_t)w * 4);
    bool alpha = false;
    for (size_t i = 3; i < n && !alpha; i += 4)
        alpha = px[i] != 255;
    povtex_image *im = &pt->imgs[pt->n++];
    memset(im, 0, sizeof *im);
    im->rgba = px;
    im->width = w;
    im->height = h;
    im->alpha = alpha;
    im->keep_alpha = true;
    im->texture = -1;
    snprintf(im->name, sizeof im->name, "rgl-tex-%016llx.png",
             (unsigned long long)content_hash(px, w, h, alpha));
    return (int)(pt->n - 1);
}

size_t povtex_image_pigment(const povtex *pt, size_t i, bool linear,
                            char buf[POVTEX_PIGMENT_MAX])
{
    /* gamma 2.2 = assumed_gamma: the file's values are used as they are
     * (docs/mapping.md "Gamma"); interpolate 2 is bilinear. */
    int n = snprintf(buf, POVTEX_PIGMENT_MAX, "uv_mapping image_map{png \"" POVTEX_DIR "/%s\" gamma 2.2%s}",
                     pt->imgs[i].name, linear ? " interpolate 2" : "");
    if (n > 0 && n < POVTEX_PIGMENT_MAX && pt->quick) {
        /* Below quality 6 POV-Ray shows a pigment's quick colour (black for
         * an image map): the image's mean, in the file's values as the
         * image map uses them (gamma 2.2 = assumed_gamma). */
        const povtex_image *im = &pt->imgs[i];
        double sum[3] = {0, 0, 0};
        size_t np = (size_t)im->width * (size_t)im->height;
        for (size_t p = 0; p < np; p++)
            for (int k = 0; k < 3; k++)
                sum[k] += im->rgba[4 * p + (size_t)k];
        double d = np ? 255.0 * (double)np : 1;
        int m = snprintf(buf + n, POVTEX_PIGMENT_MAX - (size_t)n, " quick_color rgb<%d/255,%d/255,%d/255>",
                         (int)(sum[0] / d * 255 + 0.5), (int)(sum[1] / d * 255 + 0.5),
                         (int)(sum[2] / d * 255 + 0.5));
        n = m > 0 ? n + m : -1;
    }
    return n > 0 && n < POVTEX_PIGMENT_MAX ? (size_t)n : 0;
}

size_t povtex_declared(outbuf *ob, povtex *pt, size_t i, bool linear,
                       char name[POVTEX_DECLARED_MAX])
{
    int n = snprintf(name, POVTEX_DECLARED_MAX, "rgl_img%zu%s", i, linear ? "i" : "");
    if (n <= 0 || n >= POVTEX_DECLARED_MAX)
        return 0;
    if (!pt->imgs[i].declared[linear]) {
        char im[POVTEX_PIGMENT_MAX];
        if (povtex_image_pigment(pt, i, linear, im) == 0)
            return 0;
        outbuf_puts(ob, "#declare ");
        outbuf_puts(ob, name);
        outbuf_puts(ob, "=pigment{");
        outbuf_puts(ob, strncmp(im, "uv_mapping ", 11) == 0 ? im + 11 : im);
        outbuf_puts(ob, "}\n");
        pt->imgs[i].declared[linear] = true;
    }
    return (size_t)n;
}

int povtex_alpha_pigment(outbuf *ob, povtex *pt, const scene *s, int32_t t, size_t img,
                         const float uvlo[2], const float uvhi[2], unsigned id, char *buf,
                         size_t cap)
{
    const scene_texture *tx = &s->textures[t];
    float sc[2], off[2];
    int ai = povtex_map(pt, s, t, uvlo, uvhi, true, NULL, sc, off);
    char raw[POVTEX_PIGMENT_MAX], col[POVTEX_PIGMENT_MAX];
    if (ai < 0 || povtex_image_pigment(pt, (size_t)ai, true, raw) == 0 ||
        povtex_image_pigment(pt, img, true, col) == 0)
        return -1;
    const char *rb = strncmp(raw, "uv_mapping ", 11) == 0 ? raw + 11 : raw;
    const char *cb = strncmp(col, "uv_mapping ", 11) == 0 ? col + 11 : col;
    char decl[POVTEX_PIGMENT_MAX + 64];
    snprintf(decl, sizeof decl, "#declare rgl_at%u=function{pigment{%s}}\n", id, rb);
    outbuf_puts(ob, decl);
    /* GL tests the filtered alpha At (times the vertex alpha Af): passes
     * where At > ref / Af (GL_GREATER, GL_GEQUAL), i.e. transmit below
     * 1 - ref / Af; GL_LESS, GL_LEQUAL the other side. */
    double af = tx->alpha_uses_af ? tx->alpha_af : 1;
    double th = af > 0 ? 1 - tx->alpha_ref / af : 0;
    th = th < 0 ? 0 : th > 1 ? 1 : th;
    bool below = tx->alpha_func == SCENE_CMP_GREATER || tx->alpha_func == SCENE_CMP_GEQUAL;
    const char *a = below ? cb : "rgbt<1,1,1,1>", *b = below ? "rgbt<1,1,1,1>" : cb;
    char ts[NUMFMT_F32_ROOM];
    ts[numfmt_f32(ts, (float)th)] = '\0';
    int n = snprintf(buf, cap,
                     "uv_mapping function{rgl_at%u(x,y,z).transmit}pigment_map{[0 %s][%s %s][%s "
                     "%s][1 %s]}",
                     id, a, ts, a, ts, b, b);
    return n > 0 && (size_t)n < cap ? 0 : -1;
}

size_t povtex_pigment(const povtex *pt, size_t i, const scene_texture *t,
                      char buf[POVTEX_PIGMENT_MAX])
{
    return povtex_image_pigment(pt, i, t->linear, buf);
}

/* ---- Vertex colours as an image ------------------------------------------------------ */

static int quantise(float x)
{
    return x > 0 ? (x < 1 ? (int)(x * 255.0f + 0.5f) : 255) : 0; /* NaN: 0 */
}

/* How far D = B + C - A of corner o as A leaves 0..255, worst channel. */
static int clamp_excess(const float *const c[3], int o)
{
    int worst = 0;
    for (int k = 0; k < 3; k++) {
        int d = quantise(c[(o + 1) % 3][k]) + quantise(c[(o + 2) % 3][k]) - quantise(c[o][k]);
        int e = d < 0 ? -d : d > 255 ? d - 255 : 0;
        worst = e > worst ? e : worst;
    }
    return worst;
}

static int best_origin(const float *const c[3], int *excess)
{
    int best = 0, be = clamp_excess(c, 0);
    for (int o = 1; o < 3 && be > 0; o++) {
        int e = clamp_excess(c, o);
        if (e < be)
            best = o, be = e;
    }
    *excess = be;
    return best;
}

int povtex_colour_origin(const float *const c[3])
{
    int e, o = best_origin(c, &e);
    return e <= POVTEX_CLAMP_MAX ? o : -1;
}

/* The image px (iw x ih RGBA, opaque), named by its content and kept
 * once; takes px. Returns its index, -1 when memory ran out. */
static int add_colour_image(povtex *pt, uint8_t *px, int iw, int ih)
{
    char name[POVTEX_NAME_MAX];
    snprintf(name, sizeof name, "rgl-tex-%016llx.png",
             (unsigned long long)content_hash(px, iw, ih, false));
    for (size_t i = 0; i < pt->n; i++)
        if (strcmp(pt->imgs[i].name, name) == 0) {
            tr_free(px);
            return (int)i;
        }
    if (tr_grow((void **)&pt->imgs, &pt->cap, pt->n + 1, sizeof *pt->imgs) != 0) {
        tr_free(px);
        return -1;
    }
    povtex_image *im = &pt->imgs[pt->n++];
    memset(im, 0, sizeof *im);
    memcpy(im->name, name, sizeof name);
    im->rgba = px;
    im->width = iw;
    im->height = ih;
    im->texture = -1;
    return (int)(pt->n - 1);
}

/* An opaque black iw x ih image, or NULL. */
static uint8_t *new_image(int iw, int ih)
{
    uint8_t *px = tr_realloc(NULL, (size_t)iw * (size_t)ih * 4);
    if (!px)
        return NULL;
    memset(px, 0, (size_t)iw * (size_t)ih * 4);
    for (size_t i = 3; i < (size_t)iw * (size_t)ih * 4; i += 4)
        px[i] = 255;
    return px;
}

/* Face j's 2 x 2 block at block (j % bw, j / bw) from row y0 up, and the
 * uv of its corners (uv[6 * j + 2 * k]). */
static void put_blocks(uint8_t *px, int iw, int ih, int y0, size_t bw,
                       const float *const *corners, size_t n, float *uv)
{
    for (size_t j = 0; j < n; j++) {
        const float *const *c = corners + 3 * j;
        int e, o = best_origin(c, &e);
        size_t x = (j % bw) * 2, y = (size_t)y0 + (j / bw) * 2;
        uint8_t *a = px + (y * (size_t)iw + x) * 4, *b = a + 4, *cc = a + (size_t)iw * 4,
                *d = cc + 4;
        for (int k = 0; k < 3; k++) {
            int va = quantise(c[o][k]), vb = quantise(c[(o + 1) % 3][k]),
                vc = quantise(c[(o + 2) % 3][k]), vd = vb + vc - va;
            a[k] = (uint8_t)va;
            b[k] = (uint8_t)vb;
            cc[k] = (uint8_t)vc;
            d[k] = (uint8_t)(vd < 0 ? 0 : vd > 255 ? 255 : vd);
        }
        /* Each corner samples its texel's centre, so the face stays in
         * its block. */
        static const int du[3] = {0, 1, 0}, dv[3] = {0, 0, 1};
        for (int r = 0; r < 3; r++) {
            float *t = uv + 6 * j + 2 * ((o + r) % 3);
            t[0] = (float)(((double)x + du[r] + 0.5) / iw);
            t[1] = (float)(((double)y + dv[r] + 0.5) / ih);
        }
    }
}

int povtex_colours(povtex *pt, const float *const *corners, size_t n, float *uv)
{
    size_t bw = 1;
    while (bw * bw < n)
        bw++;
    size_t bh = n ? (n + bw - 1) / bw : 1;
    if (bw * 2 > PADDED_MAX || bh * 2 > PADDED_MAX)
        return -1;
    int iw = (int)(bw * 2), ih = (int)(bh * 2);
    uint8_t *px = new_image(iw, ih);
    if (!px)
        return -1;
    put_blocks(px, iw, ih, 0, bw, corners, n, uv);
    return add_colour_image(pt, px, iw, ih);
}

int povtex_colour_grid(povtex *pt, const povgrid *g, size_t nv, float *vuv,
                       const float *const *corners, size_t n, float *uv)
{
    int gw = g->width, gh = g->height;
    size_t bw = 0, bh = 0;
    int iw = gw, ih = gh;
    if (n) {
        bw = 1;
        while (bw * bw < n)
            bw++;
        if ((size_t)gw > 2 * bw)
            bw = (size_t)gw / 2;
        bh = (n + bw - 1) / bw;
        iw = (int)(2 * bw) > gw ? (int)(2 * bw) : gw;
        if (bh * 2 > PADDED_MAX)
            return POVTEX_TOO_LARGE;
        ih = gh + (int)(bh * 2);
    }
    if (iw < 1 || ih < 1 || iw > PADDED_MAX || ih > PADDED_MAX)
        return POVTEX_TOO_LARGE;
    uint8_t *px = new_image(iw, ih);
    /* Each column's u and each row's v, made once. */
    float *cu = tr_realloc(NULL, ((size_t)gw + (size_t)gh + 1) * sizeof *cu), *rv = cu + gw;
    if (!px || !cu) {
        tr_free(px);
        tr_free(cu);
        return -1;
    }
    for (int x = 0; x < gw; x++)
        cu[x] = (float)((x + 0.5) / iw);
    for (int y = 0; y < gh; y++)
        rv[y] = (float)((y + 0.5) / ih);
    for (size_t v = 0; v < nv; v++) {
        if (g->tx[v] < 0) {
            vuv[2 * v] = vuv[2 * v + 1] = 0;
            continue;
        }
        uint8_t *t = px + ((size_t)g->ty[v] * (size_t)iw + (size_t)g->tx[v]) * 4;
        for (int k = 0; k < 3; k++)
            t[k] = (uint8_t)(g->qc[v] >> 16 * k);
        vuv[2 * v] = cu[g->tx[v]];
        vuv[2 * v + 1] = rv[g->ty[v]];
    }
    tr_free(cu);
    if (n)
        put_blocks(px, iw, ih, gh, bw, corners, n, uv);
    return add_colour_image(pt, px, iw, ih);
}
