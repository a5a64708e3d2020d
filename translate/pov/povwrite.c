/* povwrite.c: scene model -> POV-Ray 3.7 SDL (povwrite.h).
 *
 * The file, in order: a header comment, #version, global_settings with
 * assumed_gamma 2.2 (POV-Ray then does GL's arithmetic on the raw colour
 * numbers, see docs/mapping.md "Gamma"), the camera, the background, one
 * finish for unlit surfaces, then a union of everything drawn (eye space,
 * clipped to GL's near and far planes), then the lights.
 *
 * Meshes become mesh2 in povwrite_mesh2.c; here the meshes of one look and
 * transform are grouped into one (write_mesh_groups).
 */
#include "povwrite.h"

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "povwrite_internal.h"
#include "povwrite_light.h"
#include "povwrite_look.h"
#include "povwrite_mesh2.h"
#include "povwrite_solid.h"
#include "povwrite_texture.h"
#include "talloc.h"

#ifndef RAYGL_VERSION
#define RAYGL_VERSION "unknown"
#endif

povwriter *povwriter_create(void)
{
    povwriter *w = tr_realloc(NULL, sizeof *w);
    if (!w)
        return NULL;
    memset(w, 0, sizeof *w);
    dedup_init(&w->vtx, 3);
    dedup_init(&w->col, 4);
    povgrid_init(&w->grid);
    return w;
}

void povwriter_destroy(povwriter *w)
{
    if (!w)
        return;
    dedup_finish(&w->vtx);
    dedup_finish(&w->col);
    tr_free(w->vcol);
    tr_free(w->remap);
    tr_free(w->faces);
    tr_free(w->bverts);
    tr_free(w->btris);
    tr_free(w->vcolp);
    povgrid_finish(&w->grid);
    tr_free(w->mkeys);
    tr_free(w->mgroup);
    tr_free(w->gtris);
    tr_free(w->itext);
    tr_free(w->vmemo);
    tr_free(w->front);
    tr_free(w->eye);
    tr_free(w->vcorner);
    tr_free(w->offg);
    tr_free(w->vuv);
    povtex_finish(&w->tex);
    tr_free(w);
}

const povtex_image *povwriter_image(const povwriter *w, size_t i)
{
    return i < w->tex.n ? &w->tex.imgs[i] : NULL;
}

/* ---- Small writers ----------------------------------------------------------------- */

static void put_vec3f(outbuf *ob, const float v[3])
{
    char *p = outbuf_room(ob, 3 * NUMFMT_F32_ROOM + 4);
    if (!p)
        return;
    char *q = p;
    *q++ = '<';
    q += numfmt_f32(q, v[0]);
    *q++ = ',';
    q += numfmt_f32(q, v[1]);
    *q++ = ',';
    q += numfmt_f32(q, v[2]);
    *q++ = '>';
    outbuf_commit(ob, (size_t)(q - p));
}

static void put_vec3d(outbuf *ob, const double v[3])
{
    float f[3] = {(float)v[0], (float)v[1], (float)v[2]};
    put_vec3f(ob, f);
}

static void put_rgb(outbuf *ob, const float c[4])
{
    outbuf_puts(ob, "rgb");
    put_vec3f(ob, c);
}

void povwrite_put_matrix(outbuf *ob, const mat4 *to_eye)
{
    const double *m = to_eye->m;
    static const int idx[12] = {0, 1, 2, 4, 5, 6, 8, 9, 10, 12, 13, 14};
    mat4 id = mat4_identity();
    if (mat4_equal_f32(to_eye, &id))
        return;
    outbuf_puts(ob, "matrix<");
    for (int i = 0; i < 12; i++) {
        if (i)
            outbuf_putc(ob, ',');
        outbuf_f32(ob, (float)m[idx[i]]);
    }
    outbuf_puts(ob, ">\n");
}

/* A comment line's text: printable ASCII only, so no newline or other
 * byte from a trace can end the comment and start SDL. */
static void put_comment_text(outbuf *ob, const char *s)
{
    for (; s && *s; s++) {
        unsigned char c = (unsigned char)*s;
        outbuf_putc(ob, c >= 0x20 && c < 0x7f ? (char)c : '?');
    }
}

static bool finite3d(const double v[3])
{
    return isfinite(v[0]) && isfinite(v[1]) && isfinite(v[2]);
}

void povwrite_unlit_texture(outbuf *ob, const float c[4])
{
    outbuf_puts(ob, "texture{pigment{");
    if (c[3] < 1) { /* GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA: transmit 1 - alpha */
        float t[4] = {c[0], c[1], c[2], 1 - c[3]};
        outbuf_puts(ob, "rgbt<");
        for (int k = 0; k < 4; k++) {
            if (k)
                outbuf_putc(ob, ',');
            outbuf_f32(ob, t[k]);
        }
        outbuf_putc(ob, '>');
    } else {
        put_rgb(ob, c);
    }
    outbuf_puts(ob, "}}");
}

/* ---- Camera, background, lights ----------------------------------------------------- */

static void write_camera(outbuf *ob, const scene *s)
{
    const scene_camera *c = &s->camera;
    const double *v[4] = {c->location, c->right, c->up, c->direction};
    for (int i = 0; i < 4; i++)
        if (!finite3d(v[i]))
            return; /* the interpreter always supplies a finite camera */
    outbuf_puts(ob, c->kind == SCENE_CAMERA_ORTHOGRAPHIC ? "camera{orthographic"
                                                         : "camera{perspective");
    outbuf_puts(ob, "\n location ");
    put_vec3d(ob, c->location);
    outbuf_puts(ob, "\n right ");
    put_vec3d(ob, c->right);
    outbuf_puts(ob, "\n up ");
    put_vec3d(ob, c->up);
    outbuf_puts(ob, "\n direction ");
    put_vec3d(ob, c->direction);
    /* Accumulated passes through a lens (interp_accum.c). */
    if (s->focal_blur && c->kind != SCENE_CAMERA_ORTHOGRAPHIC && isfinite(s->aperture) &&
        s->aperture > 0 && finite3d(s->focal_point)) {
        outbuf_puts(ob, "\n aperture ");
        outbuf_f32(ob, (float)s->aperture);
        outbuf_puts(ob, " blur_samples ");
        outbuf_u64(ob, (uint64_t)(s->blur_samples > 0 ? s->blur_samples : 32));
        outbuf_puts(ob, " focal_point ");
        put_vec3d(ob, s->focal_point);
    }
    outbuf_puts(ob, "\n}\n");
}

/* ---- Lines and points ---------------------------------------------------------------- */

/* Appends a flat quad (corners in order, colours per corner) to the band
 * pool: two triangles in eye space. */
static int add_quad(povwriter *w, float c[4][3], const float *col[4])
{
    if (tr_grow((void **)&w->bverts, &w->cap_bverts, w->nbverts + 4, sizeof *w->bverts) != 0 ||
        tr_grow((void **)&w->btris, &w->cap_btris, w->nbtris + 2, sizeof *w->btris) != 0)
        return -1;
    uint32_t b = (uint32_t)w->nbverts;
    for (int i = 0; i < 4; i++) {
        scene_vertex *v = &w->bverts[w->nbverts++];
        memset(v, 0, sizeof *v);
        memcpy(v->pos, c[i], sizeof v->pos);
        memcpy(v->color, col[i], sizeof v->color);
    }
    scene_tri t0 = {{b, b + 1, b + 2}, b + 2}, t1 = {{b, b + 2, b + 3}, b + 3};
    w->btris[w->nbtris++] = t0;
    w->btris[w->nbtris++] = t1;
    return 0;
}

/* The band pool as one unlit mesh2 in eye space, transparent where a
 * colour's alpha says so (blending). */
static int write_bands(povwriter *w, outbuf *ob)
{
    scene_look look;
    memset(&look, 0, sizeof look);
    look.material = look.texture = look.texture1 = -1;
    for (size_t i = 0; i < w->nbverts; i++)
        if (w->bverts[i].color[3] < 1)
            look.blend = SCENE_BLEND_ALPHA;
    return povmesh2_write(w, ob, w->bverts, w->btris, w->nbtris, &look, NULL);
}

/* Lines: one mesh2 of flat quads in eye space (scene.h: the strips that
 * cover GL's pixels). */
static int write_lines(povwriter *w, outbuf *ob, const scene *s)
{
    w->nbverts = w->nbtris = 0;
    for (size_t i = 0; i < s->nlines; i++) {
        const scene_line *l = &s->lines[i];
        float c[4][3];
        bool ok = finite3f(l->p[0]) && finite3f(l->p[1]) && finite3f(l->half[0]) &&
                  finite3f(l->half[1]);
        if (!ok)
            continue;
        for (int k = 0; k < 3; k++) {
            c[0][k] = l->p[0][k] - l->half[0][k];
            c[1][k] = l->p[0][k] + l->half[0][k];
            c[2][k] = l->p[1][k] + l->half[1][k];
            c[3][k] = l->p[1][k] - l->half[1][k];
        }
        const float *col[4] = {l->color[0], l->color[1], l->color[2], l->color[3]};
        if (add_quad(w, c, col) != 0)
            return -1;
    }
    return write_bands(w, ob);
}

/* A finite point of the drawn geometry, in eye space. */
static void scene_anchor(const scene *s, float out[3])
{
    for (size_t i = 0; i < s->nmeshes; i++) {
        const scene_mesh *m = &s->meshes[i];
        if (m->proto)
            continue;
        for (size_t t = 0; t < m->tri_count; t++) {
            const float *p = s->verts[s->tris[m->first_tri + t].v[0]].pos;
            double in[4] = {p[0], p[1], p[2], 1}, o[4];
            if (m->in_eye) {
                o[0] = p[0], o[1] = p[1], o[2] = p[2], o[3] = 1;
            } else {
                mat4_apply(&m->to_eye, in, o);
            }
            if (finite3d(o) && o[3] == 1) {
                for (int k = 0; k < 3; k++)
                    out[k] = (float)o[k];
                if (finite3f(out))
                    return;
            }
        }
    }
    for (size_t i = 0; i < s->nlines; i++)
        if (finite3f(s->lines[i].p[0])) {
            memcpy(out, s->lines[i].p[0], 3 * sizeof *out);
            return;
        }
}

/* Points: their rectangles as one mesh2. They stay outside the near/far
 * clip: the interpreter kept only points whose centres GL would draw, and
 * GL then draws them whole. */
static int write_points(povwriter *w, outbuf *ob, const scene *s)
{
    w->nbverts = w->nbtris = 0;
    for (size_t i = 0; i < s->npoints; i++) {
        const scene_point *pt = &s->points[i];
        if (!finite3f(pt->p) || !finite3f(pt->right) || !finite3f(pt->up))
            continue;
        static const int sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
        float c[4][3];
        for (int v = 0; v < 4; v++)
            for (int k = 0; k < 3; k++)
                c[v][k] = pt->p[k] + (float)sx[v] * pt->right[k] + (float)sy[v] * pt->up[k];
        const float *col[4] = {pt->color, pt->color, pt->color, pt->color};
        if (add_quad(w, c, col) != 0)
            return -1;
    }
    return write_bands(w, ob);
}

/* ---- The file ------------------------------------------------------------------------- */

/* The prototypes of repeated display-list calls, one #declare each (in
 * their own space: each mesh carries its transform into it), placed by
 * `object{RGL_Lk matrix<...>}` in the union. The sphere of radius 0 keeps
 * a union of one mesh, or of none when every face was degenerate, valid. */
static int write_protos_body(povwriter *w, outbuf *ob, const scene *s)
{
    for (size_t p = 0; p < s->nprotos; p++) {
        const scene_proto *pr = &s->protos[p];
        float anchor[3] = {0, 0, 0};
        for (size_t k = 0; k < pr->nmeshes && pr->first_mesh + k < s->nmeshes; k++) {
            const scene_mesh *m = &s->meshes[pr->first_mesh + k];
            if (m->tri_count == 0)
                continue;
            const float *v = s->verts[s->tris[m->first_tri].v[0]].pos;
            double in[4] = {v[0], v[1], v[2], 1}, o[4];
            mat4_apply(&m->to_eye, in, o);
            float a[3] = {(float)o[0], (float)o[1], (float)o[2]};
            if (finite3f(a)) {
                memcpy(anchor, a, sizeof anchor);
                break;
            }
        }
        outbuf_puts(ob, "#declare RGL_L");
        outbuf_u64(ob, p);
        outbuf_puts(ob, "=union{\nsphere{");
        put_vec3f(ob, anchor);
        outbuf_puts(ob, ",0}\n");
        for (size_t k = 0; k < pr->nmeshes && pr->first_mesh + k < s->nmeshes; k++) {
            const scene_mesh *m = &s->meshes[pr->first_mesh + k];
            if (m->tri_count > 0 &&
                povmesh2_write(w, ob, s->verts, s->tris + m->first_tri, m->tri_count, &m->look,
                            &m->to_eye) != 0)
                return -1;
        }
        outbuf_puts(ob, "}\n");
    }
    return 0;
}

static int write_protos(povwriter *w, outbuf *ob, const scene *s)
{
    w->in_proto = true;
    int rc = write_protos_body(w, ob, s);
    w->in_proto = false;
    return rc;
}

static void write_clip(outbuf *ob, const scene_camera *cam)
{
    if (!cam->has_clip)
        return;
    for (int i = 0; i < 2; i++)
        if (!finite3d(cam->clip[i]) || !isfinite(cam->clip[i][3]))
            return;
    /* Keep a.p + a.w >= 0, i.e. POV-Ray's inside of plane{-a, a.w}. */
    outbuf_puts(ob, "clipped_by{");
    for (int i = 0; i < 2; i++) {
        double n[3] = {-cam->clip[i][0], -cam->clip[i][1], -cam->clip[i][2]};
        outbuf_puts(ob, "plane{");
        put_vec3d(ob, n);
        outbuf_putc(ob, ',');
        outbuf_f32(ob, (float)cam->clip[i][3]);
        outbuf_putc(ob, '}');
    }
    outbuf_puts(ob, "}\n");
}

/* The distance along a camera ray (from `from`, direction r) to the
 * near plane: the nearer of the two clip planes ahead, -1 for none. */
static double near_t(const scene_camera *cam, const double from[3], const double r[3])
{
    double best = -1;
    for (int i = 0; cam->has_clip && i < 2; i++) {
        const double *a = cam->clip[i];
        double den = dot3(a, r);
        if (den == 0 || !isfinite(den))
            continue;
        double tt = -(dot3(a, from) + a[3]) / den;
        if (isfinite(tt) && (best < 0 || tt < best) && (tt > 0 || cam->kind == SCENE_CAMERA_ORTHOGRAPHIC))
            best = tt;
    }
    return best;
}

/* Where the ray through image point (u, v) in [-1/2, 1/2]^2 meets the
 * overlay's plane. False: not finite. */
static bool overlay_point(const scene *s, double u, double v, double p[3])
{
    const scene_camera *cam = &s->camera;
    bool ortho = cam->kind == SCENE_CAMERA_ORTHOGRAPHIC;
    double from[3], r[3];
    for (int k = 0; k < 3; k++) {
        double side = u * cam->right[k] + v * cam->up[k];
        from[k] = cam->location[k] + (ortho ? side : 0);
        r[k] = cam->direction[k] + (ortho ? 0 : side);
    }
    double tt = near_t(cam, from, r);
    /* Just past the near plane: a ten-thousandth of its distance for
     * a camera with a centre, a hair along the ray for a parallel one,
     * past POV-Ray's least intersection depth (1e-4: on the camera
     * plane it meets nothing) and the float rounding of the corners. */
    double hair = 1e-3 + 1e-6 * sqrt(dot3(from, from));
    tt = ortho ? (tt < 0 && !cam->has_clip ? 0 : tt) + hair : (tt > 0 ? tt * (1 + 1e-4) : 1e-3);
    /* Depth-tested pixels at one depth: in that plane (interp_pixdepth.c). */
    if (s->overlay_at_depth) {
        const double *a = s->overlay_plane;
        double den = dot3(a, r), at = den != 0 ? -(dot3(a, from) + a[3]) / den : NAN;
        if (isfinite(at) && (at > 0 || ortho))
            tt = at;
    }
    for (int k = 0; k < 3; k++)
        p[k] = from[k] + tt * r[k];
    return finite3d(p);
}

/* Below quality 6 POV-Ray computes no image map (a pigment shows its
 * quick colour, black for one): the overlay as rectangles of one colour
 * instead, each run of equal pixels of a row, exact at every quality.
 * Past OVERLAY_MAX_RUNS runs (a picture, not a HUD) the image map is
 * kept. Returns 1 when it wrote the rectangles, 0 when it did not (too
 * many runs), -1 when memory ran out. */
#define OVERLAY_MAX_RUNS 65536
static int write_overlay_runs(outbuf *ob, const scene *s)
{
    int W = s->overlay_w, H = s->overlay_h;
    const uint8_t *px = s->overlay;
    size_t nruns = 0;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            const uint8_t *c = px + 4 * ((size_t)y * (size_t)W + (size_t)x);
            if (c[3] && (x == 0 || memcmp(c, c - 4, 4) != 0) && ++nruns > OVERLAY_MAX_RUNS)
                return 0;
        }
    if (nruns == 0)
        return 1;
    /* The runs' colours, each once: texture_list indices, found through an
     * open-addressed table of 2 to 4 slots a run (a key is never 0: its
     * alpha is not). */
    size_t nslots = 1;
    while (nslots < 2 * nruns)
        nslots *= 2;
    uint32_t *cols = tr_realloc(NULL, nruns * sizeof *cols);
    uint32_t *idx = tr_realloc(NULL, nruns * sizeof *idx);
    uint32_t *slot = tr_realloc(NULL, nslots * 2 * sizeof *slot);
    if (!cols || !idx || !slot) {
        tr_free(cols);
        tr_free(idx);
        tr_free(slot);
        return -1;
    }
    memset(slot, 0, nslots * 2 * sizeof *slot);
    size_t ncols = 0, r = 0;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            const uint8_t *c = px + 4 * ((size_t)y * (size_t)W + (size_t)x);
            if (!c[3] || (x > 0 && memcmp(c, c - 4, 4) == 0))
                continue;
            uint32_t key = (uint32_t)c[0] | (uint32_t)c[1] << 8 | (uint32_t)c[2] << 16 |
                           (uint32_t)c[3] << 24;
            size_t h = (key * 0x9e3779b1u) & (nslots - 1);
            while (slot[2 * h] && slot[2 * h] != key)
                h = (h + 1) & (nslots - 1);
            if (!slot[2 * h]) {
                slot[2 * h] = key;
                slot[2 * h + 1] = (uint32_t)ncols;
                cols[ncols++] = key;
            }
            idx[r++] = slot[2 * h + 1];
        }
    outbuf_puts(ob, "mesh2{vertex_vectors{");
    outbuf_u64(ob, 4 * nruns);
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W;) {
            const uint8_t *c = px + 4 * ((size_t)y * (size_t)W + (size_t)x);
            int e = x + 1;
            while (e < W && memcmp(c, px + 4 * ((size_t)y * (size_t)W + (size_t)e), 4) == 0)
                e++;
            if (c[3]) {
                double u0 = (double)x / W - 0.5, u1 = (double)e / W - 0.5;
                double v0 = (double)y / H - 0.5, v1 = (double)(y + 1) / H - 0.5;
                const double uv[4][2] = {{u0, v0}, {u1, v0}, {u1, v1}, {u0, v1}};
                for (int q = 0; q < 4; q++) {
                    double p[3];
                    if (!overlay_point(s, uv[q][0], uv[q][1], p))
                        p[0] = p[1] = p[2] = 0;
                    outbuf_putc(ob, ',');
                    put_vec3d(ob, p);
                }
                outbuf_putc(ob, '\n');
            }
            x = e;
        }
    outbuf_puts(ob, "}\ntexture_list{");
    outbuf_u64(ob, ncols);
    for (size_t k = 0; k < ncols; k++) {
        uint32_t c = cols[k];
        /* The PNG's values as the image map used them (gamma 2.2 =
         * assumed_gamma); its alpha as transmit. */
        const uint32_t v[4] = {c & 255, c >> 8 & 255, c >> 16 & 255, 255 - (c >> 24)};
        for (int q = 0; q < 4; q++) {
            outbuf_puts(ob, q ? "/255," : ",texture{pigment{rgbt<");
            outbuf_u64(ob, v[q]);
        }
        outbuf_puts(ob, "/255>}}\n");
    }
    outbuf_puts(ob, "}\nface_indices{");
    outbuf_u64(ob, 2 * nruns);
    for (size_t k = 0; k < nruns; k++) {
        static const int tri[2][3] = {{0, 1, 2}, {0, 2, 3}};
        for (int t = 0; t < 2; t++) {
            for (int c = 0; c < 3; c++) {
                outbuf_puts(ob, c ? "," : ",<");
                outbuf_u64(ob, 4 * (uint64_t)k + (uint64_t)tri[t][c]);
            }
            outbuf_puts(ob, ">,");
            outbuf_u64(ob, idx[k]);
        }
        outbuf_putc(ob, '\n');
    }
    outbuf_puts(ob, "}\nno_shadow no_reflection no_radiosity}\n");
    tr_free(cols);
    tr_free(idx);
    tr_free(slot);
    return 1;
}

/* Bitmaps and pixel rectangles (scene.overlay): one image covering the
 * camera's view exactly, pixel for pixel (image_map without
 * interpolation: each ray through a pixel centre meets its texel's
 * centre), just beyond the near plane, so in front of the whole scene, or
 * at the depth GL tested its pixels at (scene.overlay_at_depth).
 * Unlit (the #default finish), casting no shadow, seen in no reflection
 * or radiosity. Transparent where nothing was drawn. */
static int write_overlay(povwriter *w, outbuf *ob, const scene *s)
{
    if (w->tex.quick) {
        int rc = write_overlay_runs(ob, s);
        if (rc != 0)
            return rc < 0 ? -1 : 0;
    }
    /* Cropped to the box of what was drawn: a HUD's line of text is not a
     * frame-sized image. */
    int W = s->overlay_w, H = s->overlay_h, x0 = W, x1 = -1, y0 = H, y1 = -1;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++)
            if (s->overlay[4 * ((size_t)y * (size_t)W + (size_t)x) + 3]) {
                x0 = x < x0 ? x : x0;
                x1 = x > x1 ? x : x1;
                y0 = y < y0 ? y : y0;
                y1 = y > y1 ? y : y1;
            }
    if (x1 < 0)
        return 0; /* nothing drawn */
    int img = povtex_overlay(&w->tex, s->overlay, W, x0, y0, x1 - x0 + 1, y1 - y0 + 1);
    char pigment[POVTEX_PIGMENT_MAX];
    if (img < 0 || povtex_image_pigment(&w->tex, (size_t)img, false, pigment) == 0)
        return -1;
    double u0 = (double)x0 / W - 0.5, u1 = (double)(x1 + 1) / W - 0.5;
    double v0 = (double)y0 / H - 0.5, v1 = (double)(y1 + 1) / H - 0.5;
    const double uv[4][2] = {{u0, v0}, {u1, v0}, {u1, v1}, {u0, v1}};
    double p[4][3];
    for (int c = 0; c < 4; c++)
        if (!overlay_point(s, uv[c][0], uv[c][1], p[c]))
            return 0;
    outbuf_puts(ob, "mesh2{vertex_vectors{4");
    for (int c = 0; c < 4; c++) {
        outbuf_putc(ob, ',');
        put_vec3d(ob, p[c]);
    }
    outbuf_puts(ob, "}\nuv_vectors{4,<0,0>,<1,0>,<1,1>,<0,1>}\n"
                    "face_indices{2,<0,1,2>,<0,2,3>}\nuv_indices{2,<0,1,2>,<0,2,3>}\n"
                    "texture{pigment{");
    outbuf_puts(ob, pigment);
    outbuf_puts(ob, "}}\nno_shadow no_reflection no_radiosity}\n");
    return 0;
}

/* A display-list instance is lit by the set of its prototype's first lit
 * mesh (a list that changes lights inside it is lit by the first). */
static int32_t instance_set(const povwriter *w, const scene *s, const scene_instance *in)
{
    const scene_proto *pr = &s->protos[in->proto];
    for (size_t k = 0; k < pr->nmeshes && pr->first_mesh + k < s->nmeshes; k++) {
        int32_t set = povlight_look_set(&w->light, &s->meshes[pr->first_mesh + k].look);
        if (set >= 0)
            return set;
    }
    return POVLIGHT_UNGROUPED;
}

/* A mesh by what makes meshes one mesh2 (look and transform at float
 * precision, as scene_mesh_for joins consecutive draws): a hash of those,
 * then the mesh's place. 16 bytes a mesh: a frame may hold millions. */
typedef struct mesh_key {
    uint64_t hash;
    uint32_t index;
    uint32_t pad_;
} mesh_key;

static int mesh_key_cmp(const void *a, const void *b)
{
    const mesh_key *x = a, *y = b;
    if (x->hash != y->hash)
        return x->hash < y->hash ? -1 : 1;
    return x->index < y->index ? -1 : x->index > y->index;
}

static uint64_t hash_bytes(uint64_t h, const void *p, size_t n)
{
    const unsigned char *c = p;
    for (size_t i = 0; i < n; i++)
        h = (h ^ c[i]) * 0x100000001b3ull; /* FNV-1a */
    return h;
}

static bool same_group(const scene_mesh *a, const scene_mesh *b)
{
    return a->in_eye == b->in_eye && scene_look_equal(&a->look, &b->look) &&
           mat4_equal_f32(&a->to_eye, &b->to_eye);
}

/* The pass's meshes, those of one look and transform as one mesh2 wherever
 * they were drawn (the strips of a surface, the lit and relit parts of
 * each: docs/mapping.md section 6), so that their shared vertices are
 * written once and POV-Ray builds one object. A group is written where
 * its first mesh was drawn. */
static int write_mesh_groups(povwriter *w, outbuf *ob, const scene *s)
{
    size_t n = 0;
    if (tr_grow((void **)&w->mkeys, &w->cap_mkeys, s->nmeshes, sizeof *w->mkeys) != 0 ||
        tr_grow((void **)&w->mgroup, &w->cap_mgroup, s->nmeshes, sizeof *w->mgroup) != 0)
        return -1;
    for (size_t i = 0; i < s->nmeshes; i++) {
        const scene_mesh *m = &s->meshes[i];
        w->mgroup[i] = UINT32_MAX;
        if (m->tri_count == 0 || m->proto || !povlight_in_pass(&w->light, &m->look))
            continue;
        uint64_t h = hash_bytes(0xcbf29ce484222325ull, &m->look, sizeof m->look);
        for (int e = 0; e < 16; e++) {
            float f = (float)m->to_eye.m[e];
            h = hash_bytes(h, &f, sizeof f);
        }
        h = hash_bytes(h, &m->in_eye, sizeof m->in_eye);
        w->mkeys[n].hash = h;
        w->mkeys[n].index = (uint32_t)i;
        w->mkeys[n++].pad_ = 0;
    }
    if (n > 1)
        qsort(w->mkeys, n, sizeof *w->mkeys, mesh_key_cmp);
    /* mgroup[i]: for a group's first mesh, where its run of keys starts. */
    for (size_t a = 0; a < n;) {
        size_t b = a + 1;
        while (b < n && w->mkeys[b].hash == w->mkeys[a].hash)
            b++;
        w->mgroup[w->mkeys[a].index] = (uint32_t)a;
        a = b;
    }
    const uint32_t alone = UINT32_MAX - 1; /* a hash collision: written by itself */
    for (size_t i = 0; i < s->nmeshes; i++) {
        if (w->mgroup[i] == UINT32_MAX)
            continue;
        const scene_mesh *m = &s->meshes[i];
        const scene_tri *tris = s->tris + m->first_tri;
        size_t nt = m->tri_count;
        if (w->mgroup[i] != alone) {
            size_t a = w->mgroup[i], members = 1;
            for (size_t b = a + 1; b < n && w->mkeys[b].hash == w->mkeys[a].hash; b++) {
                const scene_mesh *g = &s->meshes[w->mkeys[b].index];
                if (same_group(m, g)) {
                    nt += g->tri_count;
                    members++;
                } else {
                    w->mgroup[w->mkeys[b].index] = alone;
                }
            }
            if (members > 1) { /* gather in drawing order */
                if (tr_grow((void **)&w->gtris, &w->cap_gtris, nt, sizeof *w->gtris) != 0)
                    return -1;
                size_t t = 0;
                for (size_t b = a; b < n && w->mkeys[b].hash == w->mkeys[a].hash; b++) {
                    const scene_mesh *g = &s->meshes[w->mkeys[b].index];
                    if (b == a || same_group(m, g)) {
                        memcpy(w->gtris + t, s->tris + g->first_tri,
                               g->tri_count * sizeof *w->gtris);
                        t += g->tri_count;
                    }
                }
                tris = w->gtris;
            }
        }
        if (povmesh2_write(w, ob, s->verts, tris, nt, &m->look, m->in_eye ? NULL : &m->to_eye) != 0)
            return -1;
    }
    return 0;
}

/* The meshes, solids and display-list instances of the writer's pass
 * (w->light.pass). */
static int write_objects(povwriter *w, outbuf *ob, const scene *s)
{
    if (write_mesh_groups(w, ob, s) != 0)
        return -1;
    povwrite_solids(ob, s, &w->light);
    for (size_t i = 0; i < s->ninstances; i++) {
        const scene_instance *in = &s->instances[i];
        if (!mat4_finite(&in->to_eye) || in->proto >= s->nprotos)
            continue;
        if (w->light.pass != POVLIGHT_ALL && instance_set(w, s, in) != w->light.pass)
            continue;
        outbuf_puts(ob, "object{RGL_L");
        outbuf_u64(ob, in->proto);
        outbuf_putc(ob, ' ');
        povwrite_put_matrix(ob, &in->to_eye);
        outbuf_puts(ob, "}\n");
    }
    return 0;
}

int povwriter_scene(povwriter *w, outbuf *ob, const scene *s, const pov_frame_info *info)
{
    outbuf_puts(ob, "// ");
    put_comment_text(ob, info && info->file_name ? info->file_name : "scene.pov");
    outbuf_puts(ob, ": written by raygl2pov " RAYGL_VERSION);
    if (info) {
        outbuf_puts(ob, " from ");
        put_comment_text(ob, info->source ? info->source : "a trace");
        outbuf_puts(ob, ", frame ");
        outbuf_u64(ob, info->frame_index);
        outbuf_puts(ob, " (stream ");
        outbuf_u64(ob, info->stream);
        outbuf_puts(ob, ", frame ");
        outbuf_u64(ob, info->number);
        outbuf_puts(ob, " of the stream)");
        if (info->frame_name) {
            outbuf_puts(ob, "\n// rayglFrameBegin name: ");
            put_comment_text(ob, info->frame_name);
        }
        for (const char *p = info->incomplete; p && *p; p += *p == '\n') {
            outbuf_puts(ob, "\n// Incomplete: ");
            for (; *p && *p != '\n'; p++) {
                unsigned char c = (unsigned char)*p;
                outbuf_putc(ob, c >= 0x20 && c < 0x7f ? (char)c : '?');
            }
        }
    }
    outbuf_puts(ob, "\n// Eye coordinates of the OpenGL frame: x right, y up, the camera looks"
                    " down -z.\n#version 3.7;\nglobal_settings{assumed_gamma 2.2}\n");
    write_camera(ob, s);
    outbuf_puts(ob, "background{");
    put_rgb(ob, s->background);
    /* Unlit surfaces: the pixel is the pigment (docs/mapping.md). Textures
     * that need another finish (issue 4) name theirs. */
    outbuf_puts(ob, "}\n#default{finish{ambient 0 diffuse 0 emission 1}}\n");

    povlight_begin(&w->light, s);
    povtex_reset(&w->tex);
    /* POV-Ray's quick colours, no image maps (-1: Quality=0) */
    w->tex.quick = s->options.quality != 0 && s->options.quality < 6;
    w->mt_count = 0;
    bool no_shadows = w->light.opt.no_shadows;
    if (write_protos(w, ob, s) != 0)
        return -1;
    povwrite_solid_declares(ob, s);
    bool any = false;
    for (size_t i = 0; i < s->nmeshes && !any; i++)
        any = s->meshes[i].tri_count > 0;
    any = any || s->nlines > 0 || s->nsolids > 0;
    if (any) {
        outbuf_puts(ob, "union{\n");
        /* POV-Ray warns about a union of one object; a sphere of radius 0
         * (never hit) at a point of the geometry keeps it quiet without
         * growing the union's bounding box. */
        float anchor[3] = {0, 0, 0};
        if (!povwrite_solid_anchor(s, anchor))
            scene_anchor(s, anchor);
        outbuf_puts(ob, "sphere{");
        put_vec3f(ob, anchor);
        outbuf_puts(ob, ",0}\n");
        if (w->light.groups) {
            /* Each light set's objects in a light_group with its lights
             * (docs/mapping.md "Lights per object"); global_lights on lets
             * the lights outside every group (rayglFrameBegin's, --light)
             * light them as they light the rest. */
            for (uint32_t k = 0; k < s->nlightsets && k < SCENE_MAX_LIGHTSETS; k++) {
                if (!w->light.used[k])
                    continue;
                outbuf_puts(ob, "light_group{\n");
                povlight_set_lights(&w->light, ob, k);
                w->light.pass = (int32_t)k;
                if (write_objects(w, ob, s) != 0)
                    return -1;
                outbuf_puts(ob, "global_lights on}\n");
            }
            w->light.pass = POVLIGHT_UNGROUPED;
        }
        int orc = write_objects(w, ob, s);
        w->light.pass = POVLIGHT_ALL;
        if (orc != 0)
            return -1;
        if (write_lines(w, ob, s) != 0)
            return -1;
        write_clip(ob, &s->camera);
        if (no_shadows)
            outbuf_puts(ob, "no_shadow\n");
        outbuf_puts(ob, "}\n");
    }
    w->mesh_no_shadow = no_shadows;
    int prc = write_points(w, ob, s);
    w->mesh_no_shadow = false;
    if (prc != 0)
        return -1;
    if (s->overlay && write_overlay(w, ob, s) != 0)
        return -1;
    povlight_lights(&w->light, ob);
    povlook_scene(ob, s);
    return ob->failed ? -1 : 0;
}

/* ---- The .ini --------------------------------------------------------------------------- */

bool pov_ini_path_ok(const char *dir)
{
    for (const unsigned char *p = (const unsigned char *)dir; *p; p++)
        if (*p < 0x20 || *p == 0x7f || *p == '"')
            return false;
    return true;
}

/* An INI value: quoted when it holds anything besides plain path bytes
 * (a ';' would start a comment, a space would end the value). */
static void put_ini_value(outbuf *ob, const char *a, const char *b)
{
    bool plain = true;
    for (int part = 0; part < 2; part++)
        for (const char *p = part ? b : a; p && *p; p++)
            if (!((*p >= 'a' && *p <= 'z') || (*p >= 'A' && *p <= 'Z') || (*p >= '0' && *p <= '9') ||
                  strchr("._-/+", *p)))
                plain = false;
    if (!plain)
        outbuf_putc(ob, '"');
    outbuf_puts(ob, a);
    if (b)
        outbuf_puts(ob, b);
    if (!plain)
        outbuf_putc(ob, '"');
    outbuf_putc(ob, '\n');
}

/* dir inside an SDL string: a backslash escapes (quotes and control
 * characters never reach here: pov_ini_path_ok). */
static void put_sdl_path(outbuf *ob, const char *dir)
{
    for (const char *p = dir; *p; p++) {
        if (*p == '\\')
            outbuf_putc(ob, '\\');
        outbuf_putc(ob, *p);
    }
}

int pov_write_folder_check(outbuf *ob, const char *dir)
{
    if (!pov_ini_path_ok(dir))
        return -1;
    size_t dl = strlen(dir);
    const char *sep = dl > 0 && dir[dl - 1] == '/' ? "" : "/";
    outbuf_puts(ob, "// Written by raygl2pov, read first by every .ini of this folder\n"
                    "// (Include_Header): their paths are relative to the folder raygl2pov\n"
                    "// ran in, and POV-Ray reads INI paths from the current folder. Run\n"
                    "// from anywhere else, the render stops here and says so.\n"
                    "#ifndef (" POV_RENDER_DECLARE ")\n"
                    "#if (!file_exists(concat(\"");
    put_sdl_path(ob, dir);
    outbuf_puts(ob, sep);
    outbuf_puts(ob, "\", input_file_name)))\n"
                    "#error concat(\"run povray from the folder raygl2pov ran in, the one that "
                    "holds ");
    put_sdl_path(ob, dir);
    outbuf_puts(ob, ": this .ini names its files from there (povray ");
    put_sdl_path(ob, dir);
    outbuf_puts(ob, sep);
    outbuf_puts(ob, "\", substr(input_file_name, 1, strlen(input_file_name) - 4), \".ini)\")\n"
                    "#end\n"
                    "#end\n");
    return ob->failed ? -1 : 0;
}

int pov_write_ini(outbuf *ob, const scene *s, const char *dir, const char *pov_file,
                  const char *png_file)
{
    if (!pov_ini_path_ok(dir) || !pov_ini_path_ok(pov_file) || !pov_ini_path_ok(png_file))
        return -1;
    size_t dl = strlen(dir);
    const char *sep = dl > 0 && dir[dl - 1] == '/' ? "" : "/";
    char out_name[4200];
    if (dl + strlen(sep) + strlen(png_file) + 1 > sizeof out_name)
        return -1;
    memcpy(out_name, dir, dl);
    strcpy(out_name + dl, sep);
    strcat(out_name, png_file);

    outbuf_puts(ob, "; Renders ");
    put_comment_text(ob, pov_file);
    outbuf_puts(ob, " at the OpenGL viewport's size: povray <this file>, run from the folder\n"
                    "; raygl2pov ran in (POV-Ray reads INI paths from the current folder).\n");
    outbuf_puts(ob, "Library_Path=");
    put_ini_value(ob, dir, NULL);
    outbuf_puts(ob, "Include_Header=" POV_FOLDER_CHECK "\n");
    outbuf_puts(ob, "Input_File_Name=");
    put_ini_value(ob, pov_file, NULL);
    outbuf_puts(ob, "Output_File_Name=");
    put_ini_value(ob, out_name, NULL);
    outbuf_puts(ob, "Width=");
    outbuf_u64(ob, (uint64_t)s->camera.width);
    outbuf_puts(ob, "\nHeight=");
    outbuf_u64(ob, (uint64_t)s->camera.height);
    if (s->antialias_depth > 0) {
        /* The frame's passes jittered the projection (interp_accum.c):
         * every pixel that differs from a neighbour is supersampled. */
        outbuf_puts(ob, "\nAntialias=On\nSampling_Method=1\nAntialias_Threshold=0\n"
                        "Antialias_Depth=");
        outbuf_u64(ob, (uint64_t)s->antialias_depth);
    } else {
        outbuf_puts(ob, "\nAntialias=Off");
    }
    outbuf_puts(ob, "\nFile_Gamma=2.2\nOutput_File_Type=N\nDisplay=Off\n"
                    "Verbose=Off\n");
    return ob->failed ? -1 : 0;
}
