/* interp_pixels.c: the raster position and what is drawn at it: glRasterPos,
 * glWindowPos, glBitmap, glDrawPixels, glCopyPixels, glPixelZoom and the
 * colour scales and biases of glPixelTransfer (GL 2.1 sections 2.13,
 * 3.6-3.7, 4.3.3).
 *
 * Bitmaps and pixel rectangles are not geometry: GL writes them to window
 * pixels. The interpreter composites them, in window coordinates, into one
 * RGBA image of the frame's viewport (scene.overlay), which the writer
 * shows in front of the scene, unlit, pixel for pixel (docs/mapping.md
 * "Bitmaps and pixel rectangles"). Where the depth test would let the 3D
 * scene hide them, or geometry drawn later covers them, they still show:
 * a note says so. A glCopyPixels under a logic op is followed by the
 * window pixels it left, read back by the recorder (@CopyPixelsResult),
 * which replace it: exact whatever the op (and the scene under it).
 */
#include "interp_internal.h"

#include <string.h>

#include "namemap.h"
#include "talloc.h"

/* ---- The raster position --------------------------------------------------------- */

/* The current colour becomes the raster colour (GL 2.1 2.13). */
static void take_colour(interp *ip)
{
    gl_attribs *a = &ip->st.a;
    memcpy(a->current.raster_color, a->current.color, sizeof a->current.raster_color);
}

/* Under lighting GL lights the raster position as a vertex at obj (w
 * divided out), with the current normal and material. */
static void take_lit_colour(interp *ip, const double obj[4])
{
    gl_attribs *a = &ip->st.a;
    double w = obj[3] != 0 ? obj[3] : 1;
    float c[4];
    interp_lit_point_colour(ip, obj[0] / w, obj[1] / w, obj[2] / w, c);
    for (int k = 0; k < 4; k++)
        a->current.raster_color[k] = c[k] > 0 ? (c[k] < 1 ? c[k] : 1) : 0;
}

/* q = m p in single precision, term by term in Mesa's order
 * (TRANSFORM_POINT). */
static void apply_f32(const mat4 *m, const float p[4], float q[4])
{
    for (int i = 0; i < 4; i++) {
        float s = (float)m->m[i] * p[0];
        s = s + (float)m->m[4 + i] * p[1];
        s = s + (float)m->m[8 + i] * p[2];
        q[i] = s + (float)m->m[12 + i] * p[3];
    }
}

void interp_rasterpos(interp *ip, const rgl_cmd *cmd)
{
    if (interp_reject_in_begin(ip))
        return;
    interp_cm_draw(ip); /* Mesa lights it from its flushed current state */
    double dobj[4] = {0, 0, 0, 1};
    float obj[4] = {0, 0, 0, 1};
    uint32_t n = cmd_value_count(cmd);
    for (uint32_t k = 0; k < n && k < 4; k++)
        obj[k] = (float)(dobj[k] = cmd_value(cmd, k));
    gl_attribs *a = &ip->st.a;
    /* In single precision as Mesa computes it (_mesa_RasterPos): a bitmap
     * lands on the floor of the position, so a position GL puts a hair
     * below a whole pixel and double arithmetic on it (or a hair above)
     * moves the bitmap a pixel (glRasterPos2i under gluOrtho2D). */
    float eye[4], clip[4];
    apply_f32(interp_matrix(ip, INTERP_MV), obj, eye);
    apply_f32(interp_matrix(ip, INTERP_PROJ), eye, clip);
    /* The position is a point clipped against the view volume: outside
     * it, the raster position is invalid. */
    float w = clip[3];
    bool in = isfinite(w) && w > 0;
    for (int k = 0; k < 3 && in; k++)
        in = isfinite(clip[k]) && clip[k] >= -w && clip[k] <= w;
    a->current.raster_valid = in;
    if (!in)
        return;
    const int32_t *vp = a->viewport.rect;
    float d = 1.0f / w, hw = (float)vp[2] * 0.5f, hh = (float)vp[3] * 0.5f;
    a->current.raster_pos[0] = clip[0] * d * hw + (hw + (float)vp[0]);
    a->current.raster_pos[1] = clip[1] * d * hh + (hh + (float)vp[1]);
    /* The depth in double: pixels placed at it meet the geometry, whose
     * depth is the scene's. */
    double deye[4], dclip[4];
    mat4_apply(interp_matrix(ip, INTERP_MV), dobj, deye);
    mat4_apply(interp_matrix(ip, INTERP_PROJ), deye, dclip);
    if (!(dclip[3] > 0) || !isfinite(dclip[2] / dclip[3])) {
        for (int k = 0; k < 4; k++)
            dclip[k] = clip[k];
    }
    double n_ = a->viewport.near, f_ = a->viewport.far;
    a->current.raster_pos[2] = n_ + (dclip[2] / dclip[3] + 1) / 2 * (f_ - n_);
    a->current.raster_pos[3] = dclip[3];
    interp_pixdepth_raster(ip, dclip);
    if (a->caps[INTERP_CAP_LIGHTING])
        take_lit_colour(ip, dobj);
    else
        take_colour(ip);
}

void interp_windowpos(interp *ip, const rgl_cmd *cmd)
{
    if (interp_reject_in_begin(ip))
        return;
    gl_attribs *a = &ip->st.a;
    double x = cmd_value(cmd, 0), y = cmd_value(cmd, 1);
    double z = cmd_value_count(cmd) > 2 ? cmd_value(cmd, 2) : 0;
    if (!isfinite(x) || !isfinite(y) || !isfinite(z)) {
        interp_diag(ip, DIAG_BAD_NUMBER, "glWindowPos: NaN or infinite position");
        return;
    }
    /* GL 2.1 2.13: never clipped, depth mapped by the depth range, the
     * colour unlit. */
    z = z > 0 ? (z < 1 ? z : 1) : 0;
    double n_ = a->viewport.near, f_ = a->viewport.far;
    a->current.raster_pos[0] = x;
    a->current.raster_pos[1] = y;
    a->current.raster_pos[2] = n_ + z * (f_ - n_);
    a->current.raster_pos[3] = 1;
    a->current.raster_valid = true;
    a->current.raster_in_camera = false; /* no eye-space depth to place it by */
    take_colour(ip);
}

void interp_pixelzoom(interp *ip, const rgl_cmd *cmd)
{
    if (interp_reject_in_begin(ip))
        return;
    double x = arg_num(&cmd->arg[0]), y = arg_num(&cmd->arg[1]);
    if (!isfinite(x) || !isfinite(y)) {
        interp_diag(ip, DIAG_BAD_NUMBER, "glPixelZoom: NaN or infinite factor");
        return;
    }
    ip->st.a.pixel.zoom[0] = (float)x;
    ip->st.a.pixel.zoom[1] = (float)y;
}

void interp_pixeltransfer(interp *ip, const rgl_cmd *cmd)
{
    if (interp_reject_in_begin(ip))
        return;
    GLenum pname = arg_enum(cmd, 0);
    double v = arg_num(&cmd->arg[1]);
    gl_attribs *a = &ip->st.a;
    static const GLenum scales[4] = {GL_RED_SCALE, GL_GREEN_SCALE, GL_BLUE_SCALE, GL_ALPHA_SCALE};
    static const GLenum biases[4] = {GL_RED_BIAS, GL_GREEN_BIAS, GL_BLUE_BIAS, GL_ALPHA_BIAS};
    for (int k = 0; k < 4; k++)
        if (pname == scales[k] || pname == biases[k]) {
            if (!isfinite(v)) {
                interp_diag(ip, DIAG_BAD_NUMBER, "glPixelTransfer: NaN or infinite value");
                return;
            }
            (pname == scales[k] ? a->pixel.scale : a->pixel.bias)[k] = (float)v;
            return;
        }
    /* Colour maps (interp_pixmap.c). */
    if (pname == GL_MAP_COLOR) {
        a->pixel.map_color = v != 0;
        return;
    }
    /* The stencil map and the depth scale and bias change only stencil and
     * depth pixels, which are not drawn (noted there); Mesa does not shift
     * or offset the colour indices it draws in RGBA (interp_pixmap.c). */
    if (pname != GL_MAP_STENCIL && pname != GL_DEPTH_SCALE && pname != GL_DEPTH_BIAS &&
        pname != GL_INDEX_SHIFT && pname != GL_INDEX_OFFSET)
        interp_bad_enum(ip, "glPixelTransfer pname", pname);
}

/* ---- The frame's image of pixels --------------------------------------------------- */

static uint64_t scene_items(const scene *s)
{
    return (uint64_t)s->ntris + s->nlines + s->npoints + s->nsolids + s->ninstances;
}

void interp_pixels_end_frame(interp *ip)
{
    scene *s = ip->scene;
    if (ip->pixels_result_due) /* a copy under a logic op drawn as it is */
        interp_note(ip, DIAG_NOTE_COLOR_MASK);
    ip->pixels_result_due = false;
    if (s)
        s->overlay_at_depth = false;
    if (!s || !s->overlay)
        return;
    /* GL would draw that geometry over the pixels; the image is in front,
     * unless it lies at the pixels' depth. */
    if (ip->not_pov)
        interp_note(ip, DIAG_NOTE_GLTF_PIXELS); /* and nothing of how they would show */
    else if (!interp_pixdepth_end_frame(ip, scene_items(s) > ip->pixels_mark &&
                                            interp_dest_after_overlay(ip, &ip->pixels_first)))
        interp_note(ip, DIAG_NOTE_PIXELS_DEPTH);
    /* The image was made at the viewport of the first pixel draw; the
     * camera may have another (fixed by a later draw): the same window
     * pixels, in the camera's rectangle. */
    const int32_t *vp = ip->cam_viewport;
    int w = vp[2], h = vp[3];
    if (vp[0] == ip->pixels_org[0] && vp[1] == ip->pixels_org[1] && w == s->overlay_w &&
        h == s->overlay_h)
        return;
    uint8_t *px = NULL;
    if (w >= 1 && h >= 1 && w <= INTERP_MAX_VIEWPORT && h <= INTERP_MAX_VIEWPORT &&
        interp_budget_texels(ip, (uint64_t)w * (uint64_t)h * 4))
        px = tr_realloc(NULL, (size_t)w * (size_t)h * 4);
    if (px) {
        memset(px, 0, (size_t)w * (size_t)h * 4);
        for (int y = 0; y < h; y++) {
            int64_t sy = (int64_t)vp[1] + y - ip->pixels_org[1];
            if (sy < 0 || sy >= s->overlay_h)
                continue;
            for (int x = 0; x < w; x++) {
                int64_t sx = (int64_t)vp[0] + x - ip->pixels_org[0];
                if (sx >= 0 && sx < s->overlay_w)
                    memcpy(px + ((size_t)y * (size_t)w + (size_t)x) * 4,
                           s->overlay + ((size_t)sy * (size_t)s->overlay_w + (size_t)sx) * 4, 4);
            }
        }
    }
    tr_free(s->overlay);
    s->overlay = px;
    s->overlay_w = px ? w : 0;
    s->overlay_h = px ? h : 0;
}

/* The overlay, made on first use at the size of the camera's viewport,
 * or the current one while no draw has fixed the camera (the first
 * pixels must not choose the frame's camera: a text overlay's projection
 * is rarely the scene's); NULL when there is no scene, or memory or the
 * budget ran out. */
static uint8_t *overlay(interp *ip)
{
    scene *s = ip->scene;
    if (!s || s->failed)
        return NULL;
    if (s->overlay)
        return s->overlay;
    const int32_t *vp = ip->camera_fixed ? ip->cam_viewport : ip->st.a.viewport.rect;
    int w = vp[2], h = vp[3];
    if (w < 1 || h < 1 || w > INTERP_MAX_VIEWPORT || h > INTERP_MAX_VIEWPORT)
        return NULL;
    size_t bytes = (size_t)w * (size_t)h * 4;
    if (!interp_budget_texels(ip, bytes))
        return NULL;
    uint8_t *px = tr_realloc(NULL, bytes);
    if (!px) {
        s->failed = true;
        return NULL;
    }
    memset(px, 0, bytes);
    s->overlay = px;
    ip->pixels_mark = scene_items(s);
    scene_mark_take(s, &ip->pixels_first);
    s->overlay_w = w;
    s->overlay_h = h;
    ip->pixels_org[0] = vp[0];
    ip->pixels_org[1] = vp[1];
    return px;
}

/* How a fragment of colour c lands on an overlay pixel: the blend
 * function GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA (with GL_BLEND) lays it
 * over what is there; otherwise it replaces it, opaque over the scene. */
static void put_pixel(uint8_t *d, const float c[4], bool over)
{
    float a = clamp01(c[3]);
    for (int k = 0; k < 3; k++) {
        float v = clamp01(c[k]);
        if (over) {
            float da = d[3] / 255.0f, dv = d[k] / 255.0f;
            float oa = a + da * (1 - a);
            v = oa > 0 ? (v * a + dv * da * (1 - a)) / oa : 0;
        }
        d[k] = (uint8_t)(clamp01(v) * 255.0f + 0.5f);
    }
    d[3] = over ? (uint8_t)(clamp01(a + d[3] / 255.0f * (1 - a)) * 255.0f + 0.5f) : 255;
}

/* Whether the frame's fragments of pixels are blended over what is there,
 * after the notes that apply to every pixel draw. */
static bool pixels_begin(interp *ip)
{
    const gl_attribs *a = &ip->st.a;
    interp_pixdepth_draw(ip);
    if (ip->scene)
        ip->pixels_mark = scene_items(ip->scene);
    return a->caps[INTERP_CAP_BLEND] && a->color_buffer.blend_src == GL_SRC_ALPHA &&
           a->color_buffer.blend_dst == GL_ONE_MINUS_SRC_ALPHA;
}

void interp_bitmap(interp *ip, const rgl_cmd *cmd)
{
    if (interp_reject_in_begin(ip))
        return;
    int64_t w = cmd->arg[0].v.i, h = cmd->arg[1].v.i;
    double xo = arg_num(&cmd->arg[2]), yo = arg_num(&cmd->arg[3]);
    double xm = arg_num(&cmd->arg[4]), ym = arg_num(&cmd->arg[5]);
    uint32_t id = (uint32_t)cmd->arg[6].v.u;
    if (w < 0 || h < 0) {
        interp_bad_value(ip, "glBitmap: negative size");
        return;
    }
    if (!isfinite(xo) || !isfinite(yo) || !isfinite(xm) || !isfinite(ym)) {
        interp_diag(ip, DIAG_BAD_NUMBER, "glBitmap: NaN or infinite origin or move");
        return;
    }
    interp_unrec_pixel_uses(ip, true, false, true);
    gl_attribs *a = &ip->st.a;
    if (!a->current.raster_valid) /* GL 2.1 3.7: ignored, the position stays */
        return;
    double *rp = a->current.raster_pos;
    size_t row = (size_t)(w + 7) / 8, need = row * (size_t)h;
    if (id && w > 0 && h > 0 && (uint64_t)w * (uint64_t)h <= (1u << 26) &&
        !interp_draw_buffer_hidden(ip)) {
        bool over = pixels_begin(ip);
        uint32_t lost = 0;
        const uint8_t *bits = ip->scene ? interp_pixels_fetch(ip, id, need, &lost) : NULL;
        uint8_t *ov = bits ? overlay(ip) : NULL;
        if (ov && interp_budget_texels(ip, (uint64_t)w * (uint64_t)h)) {
            /* The lower left corner at (floor(xr - xo), floor(yr - yo)),
             * in the overlay's coordinates. */
            double fx = floorf((float)rp[0] - (float)xo) - ip->pixels_org[0];
            double fy = floorf((float)rp[1] - (float)yo) - ip->pixels_org[1];
            int ow = ip->scene->overlay_w, oh = ip->scene->overlay_h;
            for (int64_t j = 0; j < h; j++) {
                double y = fy + (double)j;
                if (y < 0 || y >= oh)
                    continue;
                for (int64_t i = 0; i < w; i++) {
                    double x = fx + (double)i;
                    if (x < 0 || x >= ow || !((bits[(size_t)j * row + (size_t)i / 8] >> (7 - i % 8)) & 1))
                        continue;
                    put_pixel(ov + ((size_t)y * (size_t)ow + (size_t)x) * 4,
                              a->current.raster_color, over);
                }
            }
        }
    }
    /* Single precision, as GL keeps the position: a run of fractional
     * advances lands where Mesa's does. */
    rp[0] = (float)rp[0] + (float)xm;
    rp[1] = (float)rp[1] + (float)ym;
}

/* Draws w x h RGBA pixels (floats, before pixel transfer; index: from
 * colour indices) at the raster position with the pixel zoom (GL 2.1
 * 3.6.4 and 3.6.5). */
static void draw_rect(interp *ip, const float *px, int64_t w, int64_t h, bool index)
{
    const gl_attribs *a = &ip->st.a;
    interp_pixels_transfer_note(ip, index);
    bool over = pixels_begin(ip);
    uint8_t *ov = overlay(ip);
    if (!ov)
        return;
    double zx = a->pixel.zoom[0], zy = a->pixel.zoom[1];
    if (zx == 0 || zy == 0)
        return;
    /* The window pixels whose centres lie in the zoomed rectangle. */
    double xr = a->current.raster_pos[0] - ip->pixels_org[0];
    double yr = a->current.raster_pos[1] - ip->pixels_org[1];
    double x0 = fmin(xr, xr + zx * (double)w), x1 = fmax(xr, xr + zx * (double)w);
    double y0 = fmin(yr, yr + zy * (double)h), y1 = fmax(yr, yr + zy * (double)h);
    int ow = ip->scene->overlay_w, oh = ip->scene->overlay_h;
    /* Clamped as doubles first: a hostile position is far outside int64_t. */
    int64_t xa = (int64_t)fmin(ow, fmax(0, ceil(x0 - 0.5)));
    int64_t xb = (int64_t)fmin(ow, fmax(0, ceil(x1 - 0.5)));
    int64_t ya = (int64_t)fmin(oh, fmax(0, ceil(y0 - 0.5)));
    int64_t yb = (int64_t)fmin(oh, fmax(0, ceil(y1 - 0.5)));
    if (xa >= xb || ya >= yb ||
        !interp_budget_texels(ip, (uint64_t)(xb - xa) * (uint64_t)(yb - ya)))
        return;
    for (int64_t y = ya; y < yb; y++) {
        double fm = floor(((double)y + 0.5 - yr) / zy);
        if (!(fm >= 0 && fm < (double)h))
            continue;
        int64_t m = (int64_t)fm;
        for (int64_t x = xa; x < xb; x++) {
            double fk = floor(((double)x + 0.5 - xr) / zx);
            if (!(fk >= 0 && fk < (double)w))
                continue;
            int64_t k = (int64_t)fk;
            /* Pixel transfer per pixel drawn: px is kept for later draws. */
            float c[4];
            interp_pixel_transfer(ip, px + ((size_t)m * (size_t)w + (size_t)k) * 4, c);
            put_pixel(ov + ((size_t)y * (size_t)ow + (size_t)x) * 4, c, over);
        }
    }
}

/* ---- Pixel rectangles converted once a frame --------------------------------------- */

/* A rectangle drawn again (a sprite, a tiled background, a glyph) is read
 * and converted once a frame: each later draw costs the budget only the
 * pixels it writes. */
typedef struct pix_conv {
    uint32_t id;
    GLenum format, type;
    int64_t w, h;
    float *px; /* w x h RGBA, before pixel transfer */
} pix_conv;

struct interp_pixconv {
    namemap ids; /* resource -> index in v */
    pix_conv *v;
    size_t n, cap;
};

void interp_pixels_begin_frame(interp *ip)
{
    struct interp_pixconv *c = ip->pixconv;
    if (!c)
        return;
    for (size_t i = 0; i < c->n; i++)
        tr_free(c->v[i].px);
    c->n = 0;
    namemap_clear(&c->ids);
}

void interp_pixels_free(interp *ip)
{
    interp_pixels_begin_frame(ip);
    if (ip->pixconv) {
        namemap_finish(&ip->pixconv->ids);
        tr_free(ip->pixconv->v);
        tr_free(ip->pixconv);
        ip->pixconv = NULL;
    }
}

/* Keeps px (w x h, converted from resource id) for the frame's later
 * draws; false (px still the caller's) without memory for it. */
static bool conv_keep(interp *ip, uint32_t id, GLenum format, GLenum type, int64_t w, int64_t h,
                      float *px)
{
    if (!ip->pixconv) {
        ip->pixconv = tr_realloc(NULL, sizeof *ip->pixconv);
        if (!ip->pixconv)
            return false;
        memset(ip->pixconv, 0, sizeof *ip->pixconv);
        namemap_init(&ip->pixconv->ids);
    }
    struct interp_pixconv *c = ip->pixconv;
    int64_t i = namemap_get(&c->ids, id);
    if (i < 0) {
        if (c->n >= UINT32_MAX || tr_grow((void **)&c->v, &c->cap, c->n + 1, sizeof *c->v) != 0 ||
            namemap_put(&c->ids, id, (uint32_t)c->n) != 0)
            return false;
        i = (int64_t)c->n++;
    } else {
        tr_free(c->v[i].px); /* the same pixels as another format, type or size */
    }
    c->v[i] = (pix_conv){id, format, type, w, h, px};
    return true;
}

/* Converts resource id's w x h pixels of format/type and draws them. */
static void draw_pixels(interp *ip, uint32_t id, GLenum format, GLenum type, int64_t w,
                        int64_t h)
{
    if (interp_draw_buffer_hidden(ip))
        return; /* into a colour buffer the frame does not show */
    bool index = format == GL_COLOR_INDEX;
    size_t need = index ? interp_pixels_index_bytes(type, w, h) : interp_pixel_bytes(format, type, w, h);
    if (!need) {
        interp_note(ip, DIAG_NOTE_PIXELS_OTHER);
        return;
    }
    const struct interp_pixconv *c = ip->pixconv;
    int64_t i = c ? namemap_get(&c->ids, id) : -1;
    if (i >= 0 && c->v[i].format == format && c->v[i].type == type && c->v[i].w == w &&
        c->v[i].h == h) {
        draw_rect(ip, c->v[i].px, w, h, false);
        return;
    }
    uint32_t lost = 0;
    const uint8_t *src = interp_pixels_fetch(ip, id, need, &lost);
    if (!src || !interp_budget_texels(ip, (uint64_t)w * (uint64_t)h * 16))
        return;
    float *px = tr_realloc(NULL, (size_t)w * (size_t)h * 4 * sizeof *px);
    if (!px) {
        ip->scene->failed = true;
        return;
    }
    if (index)
        interp_pixels_index(ip, px, src, (size_t)w * (size_t)h, type);
    else
        interp_pixels_float(px, src, (size_t)w * (size_t)h, format, type);
    draw_rect(ip, px, w, h, index);
    /* indices are kept as the maps made them colours: not for later draws */
    if (index || !conv_keep(ip, id, format, type, w, h, px))
        tr_free(px);
}

void interp_drawpixels(interp *ip, const rgl_cmd *cmd)
{
    if (interp_reject_in_begin(ip))
        return;
    int64_t w = cmd->arg[0].v.i, h = cmd->arg[1].v.i;
    GLenum format = arg_enum(cmd, 2), type = arg_enum(cmd, 3);
    uint32_t id = (uint32_t)cmd->arg[4].v.u;
    if (w < 0 || h < 0) {
        interp_bad_value(ip, "glDrawPixels: negative size");
        return;
    }
    interp_unrec_pixel_uses(ip, true, false, true);
    if (!ip->st.a.current.raster_valid || !ip->scene || !id || w == 0 || h == 0)
        return;
    draw_pixels(ip, id, format, type, w, h);
}

void interp_copypixels(interp *ip, const rgl_cmd *cmd)
{
    if (interp_reject_in_begin(ip))
        return;
    int64_t w = cmd->arg[2].v.i, h = cmd->arg[3].v.i;
    GLenum type = arg_enum(cmd, 4);
    uint32_t id = (uint32_t)cmd->arg[5].v.u;
    if (type != GL_COLOR && type != GL_DEPTH && type != GL_STENCIL) {
        interp_bad_enum(ip, "glCopyPixels type", type);
        return;
    }
    if (w < 0 || h < 0) {
        interp_bad_value(ip, "glCopyPixels: negative size");
        return;
    }
    interp_unrec_pixel_uses(ip, true, !id, false);
    if (!ip->st.a.current.raster_valid || !ip->scene || w == 0 || h == 0)
        return;
    if (type != GL_COLOR) {
        interp_note(ip, DIAG_NOTE_PIXELS_OTHER);
        return;
    }
    if (!id) {
        interp_diag(ip, DIAG_IGNORED, "glCopyPixels: the recorder could not read the pixels");
        return;
    }
    /* Under a logic op the recorder reads back what GL left there
     * (@CopyPixelsResult, next): until it comes, the copy as it is. */
    const gl_attribs *a = &ip->st.a;
    if (ip->pixels_result_due)
        interp_note(ip, DIAG_NOTE_COLOR_MASK);
    ip->pixels_result_due = a->caps[INTERP_CAP_COLOR_LOGIC_OP] && a->color_buffer.logic_op != GL_COPY &&
                            !interp_draw_buffer_hidden(ip);
    /* The recorder read the source as 8-bit RGBA, before pixel transfer. */
    draw_pixels(ip, id, GL_RGBA, GL_UNSIGNED_BYTE, w, h);
}

/* The window pixels a glCopyPixels under a logic op left, as GL left them:
 * written into the overlay as they are, opaque. */
void interp_copypixelsresult(interp *ip, const rgl_cmd *cmd)
{
    int64_t x = cmd->arg[0].v.i, y = cmd->arg[1].v.i, w = cmd->arg[2].v.i, h = cmd->arg[3].v.i;
    uint32_t id = (uint32_t)cmd->arg[4].v.u;
    if (!ip->pixels_result_due || !ip->scene || w <= 0 || h <= 0 || !id ||
        w > INTERP_MAX_VIEWPORT || h > INTERP_MAX_VIEWPORT)
        return; /* not after such a copy, or nothing to show */
    ip->pixels_result_due = false;
    uint32_t lost = 0;
    const uint8_t *src = interp_pixels_fetch(ip, id, (size_t)w * (size_t)h * 4, &lost);
    uint8_t *ov = src ? overlay(ip) : NULL;
    if (!ov || !interp_budget_texels(ip, (uint64_t)w * (uint64_t)h))
        return;
    int ow = ip->scene->overlay_w, oh = ip->scene->overlay_h;
    for (int64_t j = 0; j < h; j++) {
        int64_t oy = y + j - ip->pixels_org[1];
        if (oy < 0 || oy >= oh)
            continue;
        for (int64_t i = 0; i < w; i++) {
            int64_t ox = x + i - ip->pixels_org[0];
            if (ox < 0 || ox >= ow)
                continue;
            uint8_t *d = ov + ((size_t)oy * (size_t)ow + (size_t)ox) * 4;
            memcpy(d, src + ((size_t)j * (size_t)w + (size_t)i) * 4, 3);
            d[3] = 255;
        }
    }
}
