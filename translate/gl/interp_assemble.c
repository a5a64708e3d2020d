/* interp_assemble.c: primitive assembly at glEnd (the vertices are
 * interp_prim.c's), face culling, polygon mode, lines, points and glRect.
 *
 * The primitive is assembled as GL does (GL 1.x 2.6.1): strips alternate
 * their winding, quads split (0,1,2)(0,2,3), or (0,1,3)(1,2,3) when
 * called from a display list or when a vertex of the draw lies outside the
 * view volume (as Mesa does: tests/programs/proj_quad_split.c), quad
 * strips take vertices
 * (2i, 2i+1, 2i+3, 2i+2), polygons are fans; incomplete primitives are
 * dropped; the provoking vertex (flat shading) is the last vertex of each
 * triangle, quad or segment and the first of a polygon (table 2.2).
 * Facing follows the window-space winding (2.14.1 and 3.5.1), computed in
 * clip space so that primitives crossing the eye plane still face right.
 * Lines and points leave the pool again: they become eye-space segments and
 * squares sized to their pixel width.
 */
#include "interp_internal.h"

#include <string.h>

#include "talloc.h"

typedef struct assembly {
    interp *ip;
    scene *s;
    uint32_t base;  /* absolute index of the primitive's first vertex */
    bool facing;    /* facing must be computed (culling or mixed modes) */
    bool back;      /* with facing: the triangle being filled is a back face */
    bool cull_front, cull_back;
    bool swap;      /* glFrontFace(GL_CW): reorder so that front is CCW */
    bool check_bad; /* some vertex is not finite */
    bool flat;
    bool first; /* GL_FIRST_VERTEX_CONVENTION (glProvokingVertex) */
    float line_width, point_size;
    bool line_smooth, point_smooth;
    bool point_sprite; /* GL_POINT_SPRITE: square, its size not rounded (GL 2.1 3.3.1) */
    bool point_params; /* glPointParameter away from its defaults */
    bool list_quads; /* quads split along v1-v3, as Mesa does in a list or when clipping */
    bool stipple;       /* glLineStipple applies (interp_stipple.c) */
    double stipple_s;   /* GL's stipple counter (a float in Mesa) */
    bool step;          /* a line draw (not outlined faces, which interp_proj may step) */
    uint32_t segments;  /* segments added so far: each after the first a painter's step */
    uint32_t painter;   /* the draw's own painter's shift (ip->painter when it began) */
    int relit;          /* INTERP_RELIT_*: filled faces lit as GL does (interp_relit.c) */
    bool lit_edges;     /* outlined (GL_LINE, GL_POINT) lit faces: GL's lit colours, relit_col */
    bool fog_split;     /* triangles behind the eye get their own fog (interp_fogbehind.c) */
    const scene_look *look; /* the mesh's look, and where its vertices are, for fog_split */
    const mat4 *to_eye;
    bool in_eye;
    bool alpha_test; /* interp_alpha_testing: faces may be discarded */
    bool fill_checks; /* the stencil, alpha_test or fog_split: fill_tri_checks */
    scene_mesh *mesh;
    /* The GL-lit pass's triangles take the copies of their corners
     * (interp_relit_vertices): pool index of vertex k's copy; NULL for
     * the vertices themselves (base + k). */
    const uint32_t *copy;
} assembly;

/* The provoking vertex of a primitive whose last and first vertices are
 * `last` and `first` (GL 3.2 table 2.12). Quads and quad strips keep the
 * last vertex: Mesa's GL_QUADS_FOLLOW_PROVOKING_VERTEX_CONVENTION is
 * false (EXT_provoking_vertex allows either). */
static uint32_t pv(const assembly *as, uint32_t last, uint32_t first)
{
    return as->first ? first : last;
}

static bool vertex_ok(const scene_vertex *v)
{
    return isfinite(v->pos[0]) && isfinite(v->pos[1]) && isfinite(v->pos[2]);
}

/* Eye-space position of a pool vertex (already there when prim_in_eye). */
static bool eye_pos(const interp *ip, const scene_vertex *v, double out[3])
{
    if (ip->prim_in_eye) {
        for (int k = 0; k < 3; k++)
            out[k] = v->pos[k];
    } else {
        double in[4] = {v->pos[0], v->pos[1], v->pos[2], 1}, o[4];
        mat4_apply(&ip->prim_to_eye, in, o);
        if (!(o[3] > 0))
            return false;
        for (int k = 0; k < 3; k++)
            out[k] = o[k] / o[3];
    }
    return isfinite(out[0]) && isfinite(out[1]) && isfinite(out[2]);
}

/* The colour GL rasterises pool vertex i with: its own, or for an
 * outlined lit face GL's lit colour (the pool holds the colour POV-Ray
 * lights a filled face with). */
static const float *edge_colour(const assembly *as, uint32_t i)
{
    if (as->lit_edges)
        return as->ip->relit_col[i - as->base];
    return as->s->verts[i].color;
}

/* The next segment of a line draw without a depth test: one painter's
 * step nearer than the one before, as GL draws it over what came before
 * where both light a pixel (a strip's joints, wide lines, crossings).
 * *delta takes eye points of the draw's own shift (base) to the new one. */
static bool painter_step(interp *ip, uint32_t base, mat4 *delta)
{
    const gl_attribs *a = &ip->st.a;
    if ((a->caps[INTERP_CAP_DEPTH_TEST] && (a->depth.func == GL_LESS || a->depth.func == GL_LEQUAL)) ||
        ip->painter >= INTERP_PAINTER_MAX || !ip->scene)
        return false;
    mat4 from = mat4_identity(), inv;
    interp_painter_apply(ip, base, &from);
    if (!mat4_invert(&from, &inv))
        return false;
    *delta = inv;
    interp_painter_apply(ip, ++ip->painter, delta);
    return true;
}

/* A segment of the primitive, between pool vertices i0 and i1, with the
 * colours GL gives it (flat: the provoking vertex's). */
static void add_segment(assembly *as, uint32_t i0, uint32_t i1, uint32_t provoking)
{
    interp *ip = as->ip;
    const scene_vertex *v0 = &as->s->verts[i0], *v1 = &as->s->verts[i1];
    interp_line ln;
    double t[2];
    if (ip->stencil.only)
        return; /* into the stencil buffer alone (not followed: a note) */
    ip->segments++;
    if (!eye_pos(ip, v0, ln.p[0]) || !eye_pos(ip, v1, ln.p[1]) ||
        !interp_clip_segment(ip, ln.p[0], ln.p[1], &t[0], &t[1]))
        return;
    const float *c0 = edge_colour(as, as->flat ? provoking : i0);
    const float *c1 = edge_colour(as, as->flat ? provoking : i1);
    /* cut by a clip plane: the colour there */
    for (int e = 0; e < 2; e++)
        for (int k = 0; k < 4; k++)
            ln.color[e][k] = (float)(c0[k] + (c1[k] - c0[k]) * t[e]);
    ln.width = as->line_width;
    ln.smooth = as->line_smooth;
    ln.stipple = as->stipple;
    ln.have_win = t[0] == 0 && t[1] == 1 && interp_gl_window(ip, v0->pos, ln.win[0]) &&
                  interp_gl_window(ip, v1->pos, ln.win[1]);
    mat4 delta;
    if (as->step && as->segments++ > 0 && painter_step(ip, as->painter, &delta))
        for (int e = 0; e < 2; e++) {
            double in[4] = {ln.p[e][0], ln.p[e][1], ln.p[e][2], 1}, o[4];
            mat4_apply(&delta, in, o);
            for (int k = 0; k < 3; k++)
                ln.p[e][k] = o[k] / o[3];
        }
    interp_add_line(ip, &ln, &as->stipple_s);
}

/* GL's point (GL 1.x 3.3) clipped by its centre alone (2.12): inside the
 * view volume it is drawn whole, outside not at all. */
static void add_point(assembly *as, uint32_t i, uint32_t colour_from)
{
    double p[3];
    if (as->ip->stencil.only)
        return;
    if (!eye_pos(as->ip, &as->s->verts[i], p) || !interp_clip_point(as->ip, p))
        return;
    double size = as->point_size, fade = 1;
    if (as->point_params)
        size = interp_point_size(&as->ip->st.a, p, &fade);
    /* GL fades points below the threshold when multisampling (GL 2.1 3.3) */
    if (size < as->ip->st.a.point.fade_threshold)
        interp_note(as->ip, DIAG_NOTE_POINT_FADE);
    float c[4];
    memcpy(c, edge_colour(as, colour_from), sizeof c);
    c[3] *= (float)fade;
    double win[2];
    bool gl_win = interp_gl_window(as->ip, as->s->verts[i].pos, win);
    size_t first = as->s->npoints;
    interp_add_point(as->ip, p, gl_win ? win : NULL, c, size, as->point_smooth, as->point_params,
                     as->point_sprite);
    bool taken = as->s->npoints > first;
    for (size_t k = first; k < as->s->npoints && taken; k++)
        taken = interp_point_textured(as->ip, &as->s->points[k], &as->s->verts[i],
                                      as->point_smooth);
    if (taken)
        as->s->npoints = first; /* textured squares instead (interp_sprite.c) */
}

/* Whether a vertex of the primitive lies outside the view volume. Mesa
 * (llvmpipe) then draws the whole draw through its clipper, which splits
 * quads (v0,v1,v3)(v1,v2,v3) (docs/mapping.md "Quad and polygon
 * decomposition"; tests/programs/proj_quad_split.c). */
static bool crosses_view_volume(const interp *ip, uint32_t n)
{
    const mat4 *m = &ip->prim_clip;
    const scene_vertex *v = ip->scene->verts + ip->prim_first;
    for (uint32_t i = 0; i < n; i++) {
        double in[4] = {v[i].pos[0], v[i].pos[1], v[i].pos[2], 1}, c[4];
        mat4_apply(m, in, c);
        if (!(c[3] > 0) || fabs(c[0]) > c[3] || fabs(c[1]) > c[3] || fabs(c[2]) > c[3])
            return true;
    }
    return false;
}

/* Clip-space x, y, w of every vertex of the primitive, for facing, and
 * x/w, y/w: each vertex is in up to three triangles of a strip, whose
 * areas divided by w there for every edge. */
static bool compute_clip(interp *ip, uint32_t n)
{
    if (n > ip->cap_clipv &&
        tr_grow((void **)&ip->clipv, &ip->cap_clipv, n, sizeof *ip->clipv) != 0)
        return false;
    const mat4 *m = &ip->prim_clip;
    const scene_vertex *v = ip->scene->verts + ip->prim_first;
    for (uint32_t i = 0; i < n; i++) {
        double x = v[i].pos[0], y = v[i].pos[1], z = v[i].pos[2];
        ip->clipv[i][0] = m->m[0] * x + m->m[4] * y + m->m[8] * z + m->m[12];
        ip->clipv[i][1] = m->m[1] * x + m->m[5] * y + m->m[9] * z + m->m[13];
        ip->clipv[i][2] = m->m[3] * x + m->m[7] * y + m->m[11] * z + m->m[15];
        ip->clipv[i][3] = ip->clipv[i][0] / ip->clipv[i][2];
        ip->clipv[i][4] = ip->clipv[i][1] / ip->clipv[i][2];
    }
    return true;
}

/* Counter-clockwise in window space? For polygons wholly in front of the
 * eye, the signed area of the projection; otherwise the sign of the
 * homogeneous determinant of the first three vertices, which gives the
 * winding of the visible, clipped part. idx are relative to the base. */
static inline bool is_ccw3(const interp *ip, uint32_t i0, uint32_t i1, uint32_t i2)
{
    double (*c)[5] = ip->clipv;
    const double *a = c[i0], *b = c[i1], *d = c[i2];
    if (a[2] > 0 && b[2] > 0 && d[2] > 0) { /* is_ccw's loop unrolled, same sums */
        double area = 0;
        area += a[3] * b[4] - b[3] * a[4];
        area += b[3] * d[4] - d[3] * b[4];
        area += d[3] * a[4] - a[3] * d[4];
        return area > 0;
    }
    double det = a[0] * (b[1] * d[2] - b[2] * d[1]) - a[1] * (b[0] * d[2] - b[2] * d[0]) +
                 a[2] * (b[0] * d[1] - b[1] * d[0]);
    return det > 0;
}

static bool is_ccw(const interp *ip, const uint32_t *idx, int n)
{
    double (*c)[5] = ip->clipv;
    if (n == 3) /* strips and triangles */
        return is_ccw3(ip, idx[0], idx[1], idx[2]);
    bool all_front = true;
    for (int k = 0; k < n; k++)
        if (!(c[idx[k]][2] > 0))
            all_front = false;
    if (all_front) {
        double area = 0;
        for (int k = 0; k < n; k++) {
            const double *a = c[idx[k]], *b = c[idx[(k + 1) % n]];
            area += a[3] * b[4] - b[3] * a[4];
        }
        return area > 0;
    }
    const double *a = c[idx[0]], *b = c[idx[1]], *d = c[idx[2]];
    double det = a[0] * (b[1] * d[2] - b[2] * d[1]) - a[1] * (b[0] * d[2] - b[2] * d[0]) +
                 a[2] * (b[0] * d[1] - b[1] * d[0]);
    return det > 0;
}

/* What fill_tri does besides adding the triangle, when fill_checks says
 * there is any: the stencil region, the alpha test, the fog behind the
 * eye. False when the face is not drawn. */
static bool fill_tri_checks(assembly *as, uint32_t a, uint32_t b, uint32_t c)
{
    /* its window region, for later stencil tests (of the faces that write) */
    if (as->ip->stencil.write && (as->ip->stencil.tri_faces & (as->back ? 2 : 1))) {
        double p[3][3];
        const scene_vertex *v = as->s->verts + as->base;
        if (eye_pos(as->ip, &v[a], p[0]) && eye_pos(as->ip, &v[b], p[1]) &&
            eye_pos(as->ip, &v[c], p[2]))
            interp_stencil_tri(as->ip, p);
    }
    if (!as->mesh || as->ip->stencil.only)
        return false;
    const uint32_t abc[3] = {a, b, c};
    if (as->alpha_test && !interp_alpha_face(as->ip, abc, 3, as->mesh->look.texture))
        return false;
    if (as->fog_split) {
        const uint32_t rel[3] = {a, b, c};
        as->mesh = interp_fog_behind_mesh(as->ip, as->look, as->to_eye, as->in_eye, as->base, rel);
        if (!as->mesh)
            return false;
    }
    return true;
}

#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void fill_tri(assembly *as, uint32_t a, uint32_t b, uint32_t c, uint32_t provoking)
{
    if (as->fill_checks ? !fill_tri_checks(as, a, b, c) : !as->mesh)
        return;
    const uint32_t *cp = as->copy;
    uint32_t pa = cp ? cp[a] : as->base + a, pb = cp ? cp[b] : as->base + b;
    uint32_t pc = cp ? cp[c] : as->base + c, pp = cp ? cp[provoking] : as->base + provoking;
    if (as->swap)
        scene_add_tri(as->s, pa, pc, pb, pp);
    else
        scene_add_tri(as->s, pa, pb, pc, pp);
}

/* relit_keep's room for one more triangle, out of its way. */
#if defined(__GNUC__)
__attribute__((noinline))
#endif
static bool relit_grow(assembly *as)
{
    interp *ip = as->ip;
    if (tr_grow((void **)&ip->relit_tris, &ip->cap_relit_tris, ip->nrelit_tris + 1,
                sizeof *ip->relit_tris) != 0) {
        as->s->failed = true;
        return false;
    }
    return true;
}

/* Keeps a filled triangle for the GL-lit pass (interp_relit.c): its
 * corners get GL's colour there, and it goes to that pass's mesh. */
static inline void relit_keep(assembly *as, uint32_t a, uint32_t b, uint32_t c,
                              uint32_t provoking)
{
    interp *ip = as->ip;
    if (ip->nrelit_tris >= ip->cap_relit_tris && !relit_grow(as))
        return;
    uint32_t *t = ip->relit_tris[ip->nrelit_tris++];
    t[0] = a, t[1] = b, t[2] = c, t[3] = provoking;
    ip->relit_need[a] = ip->relit_need[b] = ip->relit_need[c] = ip->relit_need[provoking] = 1;
}

/* One polygon (triangle, quad or GL_POLYGON) with vertices idx (relative)
 * and its provoking vertex. */
static void emit_polygon(assembly *as, const uint32_t *idx, int n, uint32_t provoking)
{
    interp *ip = as->ip;
    const gl_attribs *a = &ip->st.a;
    if (as->check_bad)
        for (int k = 0; k < n; k++)
            if (!vertex_ok(&as->s->verts[as->base + idx[k]]))
                return;
    GLenum mode = a->polygon.mode[0];
    bool front = true;
    if (as->facing) {
        front = is_ccw(ip, idx, n) != as->swap;
        if ((front && as->cull_front) || (!front && as->cull_back))
            return;
        if (!front && ip->stencil.two_side)
            interp_note(ip, DIAG_NOTE_STENCIL_TWO_SIDE);
        as->back = !front;
        mode = a->polygon.mode[front ? 0 : 1];
    }
    if (as->relit == INTERP_RELIT_PROBE) {
        if (!front && mode == GL_FILL)
            interp_note(ip, DIAG_NOTE_RELIT_SPECULAR);
    } else if (as->relit && mode == GL_FILL) {
        bool gl_lit = as->relit == INTERP_RELIT_ALL || !front;
        if (gl_lit) {
            for (int k = 1; k + 1 < n; k++)
                relit_keep(as, idx[0], idx[k], idx[k + 1], provoking);
            return;
        }
    }
    if (mode == GL_FILL) {
        for (int k = 1; k + 1 < n; k++)
            fill_tri(as, idx[0], idx[k], idx[k + 1], provoking);
        return;
    }
    as->stipple_s = 0; /* each polygon restarts the stipple (NOTE_STIPPLE) */
    for (int k = 0; k < n; k++) {
        if (!(ip->edge[idx[k]] & 1))
            continue; /* GL draws only boundary edges (and their vertices) */
        if (mode == GL_LINE)
            add_segment(as, as->base + idx[k], as->base + idx[(k + 1) % n], as->base + provoking);
        else
            add_point(as, as->base + idx[k], as->flat ? as->base + provoking : as->base + idx[k]);
    }
}

/* Every mode takes edge flags, strips and fans too: GL 2.1 2.6.2 says
 * their edges are all boundary edges, but Mesa (gallium's draw module,
 * the reference here) flags edge (a, b) of each triangle or quad it
 * emits by a's flag, in the vertex orders below (tests/programs/
 * edgeflag_strips.c). */
static void assemble_polygons(assembly *as, GLenum mode, uint32_t n)
{
    uint32_t t[4];
    switch (mode) {
    case GL_TRIANGLES:
        for (uint32_t i = 0; i + 3 <= n; i += 3) {
            t[0] = i, t[1] = i + 1, t[2] = i + 2;
            emit_polygon(as, t, 3, pv(as, i + 2, i));
        }
        break;
    case GL_TRIANGLE_STRIP:
        for (uint32_t i = 0; i + 3 <= n; i++) {
            if (i % 2 == 0)
                t[0] = i, t[1] = i + 1;
            else
                t[0] = i + 1, t[1] = i;
            t[2] = i + 2;
            emit_polygon(as, t, 3, pv(as, i + 2, i));
        }
        break;
    case GL_TRIANGLE_FAN:
        for (uint32_t i = 0; i + 3 <= n; i++) {
            t[0] = 0, t[1] = i + 1, t[2] = i + 2;
            emit_polygon(as, t, 3, pv(as, i + 2, i + 1));
        }
        break;
    case GL_QUADS:
        for (uint32_t i = 0; i + 4 <= n; i += 4) {
            /* The fan starts at v1 for the v1-v3 diagonal: same edges. */
            uint32_t f = as->list_quads ? 1 : 0;
            for (uint32_t k = 0; k < 4; k++)
                t[k] = i + (k + f) % 4;
            emit_polygon(as, t, 4, i + 3);
        }
        break;
    case GL_QUAD_STRIP:
        for (uint32_t i = 0; i + 4 <= n; i += 2) {
            t[0] = i, t[1] = i + 1, t[2] = i + 3, t[3] = i + 2;
            emit_polygon(as, t, 4, i + 3);
        }
        break;
    case GL_POLYGON:
        if (n >= 3) {
            uint32_t *all = tr_realloc(NULL, n * sizeof *all);
            if (!all) {
                as->s->failed = true;
                return;
            }
            for (uint32_t i = 0; i < n; i++)
                all[i] = i;
            emit_polygon(as, all, (int)n, 0);
            tr_free(all);
        }
        break;
    default:
        break;
    }
}

/* Fast path: every face filled, nothing culled, every vertex finite. */
static void assemble_filled(assembly *as, GLenum mode, uint32_t n)
{
    switch (mode) {
    case GL_TRIANGLES:
        for (uint32_t i = 0; i + 3 <= n; i += 3)
            fill_tri(as, i, i + 1, i + 2, pv(as, i + 2, i));
        break;
    case GL_TRIANGLE_STRIP:
        for (uint32_t i = 0; i + 3 <= n; i++) {
            if (i % 2 == 0)
                fill_tri(as, i, i + 1, i + 2, pv(as, i + 2, i));
            else
                fill_tri(as, i + 1, i, i + 2, pv(as, i + 2, i));
        }
        break;
    case GL_TRIANGLE_FAN:
        for (uint32_t i = 0; i + 3 <= n; i++)
            fill_tri(as, 0, i + 1, i + 2, pv(as, i + 2, i + 1));
        break;
    case GL_QUADS:
        for (uint32_t i = 0; i + 4 <= n; i += 4) {
            if (as->list_quads) {
                fill_tri(as, i, i + 1, i + 3, i + 3);
                fill_tri(as, i + 1, i + 2, i + 3, i + 3);
            } else {
                fill_tri(as, i, i + 1, i + 2, i + 3);
                fill_tri(as, i, i + 2, i + 3, i + 3);
            }
        }
        break;
    case GL_QUAD_STRIP:
        for (uint32_t i = 0; i + 4 <= n; i += 2) {
            fill_tri(as, i, i + 1, i + 3, i + 3);
            fill_tri(as, i, i + 3, i + 2, i + 3);
        }
        break;
    case GL_POLYGON:
        for (uint32_t i = 1; i + 1 < n; i++)
            fill_tri(as, 0, i, i + 1, 0);
        break;
    default:
        break;
    }
}

/* emit_polygon for one triangle when both faces are filled, every vertex
 * finite and facing is needed (culling, or back faces lit as GL does).
 * Inline in each loop: a call per triangle cost a fifth of its work. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline void facing_tri(assembly *as, uint32_t a, uint32_t b, uint32_t c,
                              uint32_t provoking)
{
    bool front = is_ccw3(as->ip, a, b, c) != as->swap;
    if (front ? as->cull_front : as->cull_back)
        return;
    if (!front && as->ip->stencil.two_side) /* it took the front faces' stencil */
        interp_note(as->ip, DIAG_NOTE_STENCIL_TWO_SIDE);
    as->back = !front;
    if (as->relit && (as->relit == INTERP_RELIT_ALL || !front))
        relit_keep(as, a, b, c, provoking);
    else
        fill_tri(as, a, b, c, provoking);
}

/* The triangle modes through facing_tri: one face test per triangle, in
 * assemble_polygons' order. */
static bool assemble_facing(assembly *as, GLenum mode, uint32_t n)
{
    switch (mode) {
    case GL_TRIANGLES:
        for (uint32_t i = 0; i + 3 <= n; i += 3)
            facing_tri(as, i, i + 1, i + 2, pv(as, i + 2, i));
        return true;
    case GL_TRIANGLE_STRIP:
        for (uint32_t i = 0; i + 3 <= n; i++) {
            if (i % 2 == 0)
                facing_tri(as, i, i + 1, i + 2, pv(as, i + 2, i));
            else
                facing_tri(as, i + 1, i, i + 2, pv(as, i + 2, i));
        }
        return true;
    case GL_TRIANGLE_FAN:
        for (uint32_t i = 0; i + 3 <= n; i++)
            facing_tri(as, 0, i + 1, i + 2, pv(as, i + 2, i + 1));
        return true;
    default:
        return false;
    }
}

static void assemble_lines(assembly *as, GLenum mode, uint32_t n)
{
    uint32_t b = as->base;
    switch (mode) {
    case GL_POINTS:
        for (uint32_t i = 0; i < n; i++)
            if (!as->check_bad || vertex_ok(&as->s->verts[b + i]))
                add_point(as, b + i, b + i);
        break;
    case GL_LINES:
        for (uint32_t i = 0; i + 2 <= n; i += 2) {
            as->stipple_s = 0; /* GL restarts the stipple per segment */
            add_segment(as, b + i, b + i + 1, pv(as, b + i + 1, b + i));
        }
        break;
    case GL_LINE_STRIP:
    case GL_LINE_LOOP:
        for (uint32_t i = 0; i + 2 <= n; i++)
            add_segment(as, b + i, b + i + 1, pv(as, b + i + 1, b + i));
        if (mode == GL_LINE_LOOP && n >= 2) /* table 2.2: provoking is vertex 1 */
            add_segment(as, b + n - 1, b, pv(as, b, b + n - 1));
        break;
    default:
        break;
    }
}

/* Moves the primitive's vertices into eye space (projective or singular
 * transforms that a POV-Ray matrix cannot carry). Normals follow with the
 * inverse transpose of the linear part, as GL transforms them. */
static void vertices_to_eye(interp *ip, uint32_t n)
{
    scene_vertex *v = ip->scene->verts + ip->prim_first;
    mat4 inv, nt;
    bool have_nt = mat4_invert(&ip->prim_to_eye, &inv);
    nt = mat4_transpose(&inv);
    for (uint32_t i = 0; i < n; i++) {
        double in[4] = {v[i].pos[0], v[i].pos[1], v[i].pos[2], 1}, o[4];
        mat4_apply(&ip->prim_to_eye, in, o);
        if (o[3] > 0 && isfinite(o[3])) {
            for (int k = 0; k < 3; k++)
                v[i].pos[k] = (float)(o[k] / o[3]);
        } else {
            v[i].pos[0] = v[i].pos[1] = v[i].pos[2] = NAN; /* behind the eye */
        }
        if (have_nt) {
            double nin[4] = {v[i].normal[0], v[i].normal[1], v[i].normal[2], 0}, no[4];
            mat4_apply(&nt, nin, no);
            for (int k = 0; k < 3; k++)
                v[i].normal[k] = (float)no[k];
        }
    }
}

/* Whether the open primitive's vertices (in the pool from prim_first on;
 * none for a solid, of the current colour) share one colour. */
static bool prim_one_colour(const interp *ip)
{
    const scene *s = ip->scene;
    for (size_t i = ip->prim_first + 1; i < s->nverts; i++)
        if (memcmp(s->verts[i].color, s->verts[ip->prim_first].color, sizeof(float[4])) != 0)
            return false;
    return true;
}

scene_look interp_current_look(interp *ip)
{
    scene_look look;
    memset(&look, 0, sizeof look);
    look.lit = ip->st.a.caps[INTERP_CAP_LIGHTING] && !interp_vertex_lit(ip);
    look.flat = ip->st.a.lighting.shade_model == GL_FLAT;
    look.blend = ip->prim_blend;
    look.filter = ip->prim_filter;
    look.fog = ip->st.a.caps[INTERP_CAP_FOG] && !ip->prim_fog_vertex;
    if (ip->st.a.caps[INTERP_CAP_ALPHA_TEST]) {
        GLenum f = ip->st.a.color_buffer.alpha_func;
        look.alpha_test = f == GL_GREATER || f == GL_GEQUAL ? SCENE_ALPHA_ABOVE
                          : f == GL_NEVER                   ? SCENE_ALPHA_NEVER
                          : f == GL_ALWAYS                  ? SCENE_ALPHA_OFF
                                                            : SCENE_ALPHA_OTHER;
        if (look.alpha_test == SCENE_ALPHA_ABOVE)
            look.alpha_ref = ip->st.a.color_buffer.alpha_ref;
    }
    look.material = look.lit ? interp_lit_material(ip) : -1;
    if (look.lit && look.material < 0)
        look.lit = 0;
    look.texture = interp_texture_for_unit(ip, ip->draw_unit[0]);
    look.texture1 = interp_texture_for_unit(ip, ip->draw_unit[1]);
    if (look.texture1 >= 0) {
        const scene_texture *t0 = look.texture >= 0 ? &ip->scene->textures[look.texture] : NULL;
        const scene_texture *t1 = &ip->scene->textures[look.texture1];
        bool one_colour = t0 &&
                          !(t0->env_mode == SCENE_ENV_MODULATE &&
                            t1->env_mode == SCENE_ENV_MODULATE) &&
                          !t0->colour_is_texel && (look.lit || !look.flat);
        if (t1->colour_is_texel) /* the second unit's texel replaces the first's result */
            look.texture = -1;
        else if ((one_colour && (look.lit || !prim_one_colour(ip))) ||
                 (t0 && look.blend != SCENE_BLEND_OPAQUE))
            interp_note(ip, DIAG_NOTE_MULTITEX); /* see the note's text */
        else if (one_colour) /* unlit, and every vertex has the colour it is combined with */
            interp_note_held(ip, DIAG_NOTE_MULTITEX, "the draw's vertices share one colour");
    }
    if (look.texture < 0 && look.texture1 >= 0) {
        /* An incomplete (or replaced) first unit passes its input on: the
         * second unit draws alone, with its coordinates in tex. */
        look.texture = look.texture1;
        look.texture1 = -1;
        ip->prim_tex_from1 = true;
    }
    look.names = interp_names_for_draw(ip);
    interp_scissor_look(ip, &look);
    interp_pstipple_look(ip, &look);
    look.clip = interp_clip_look(ip);
    interp_stencil_look(ip, &look);
    interp_lightset_textured(ip, &look);
    interp_fogsec_look(ip, &look);
    return look;
}

/* GL lights the normal as transformed (2.11.3); POV-Ray always normalises
 * it. Says so when a lit primitive's normals are not unit length in eye
 * space (GL_NORMALIZE off, GL_RESCALE_NORMAL not making them so). */
static void check_normals(interp *ip, uint32_t n)
{
    const gl_attribs *a = &ip->st.a;
    if (a->caps[INTERP_CAP_NORMALIZE] || ip->prim_in_eye || interp_note_said(ip, DIAG_NOTE_NORMALS))
        return;
    mat4 inv;
    if (!mat4_invert(interp_matrix(ip, INTERP_MV), &inv))
        return;
    double r = 1;
    if (a->caps[INTERP_CAP_RESCALE_NORMAL]) {
        r = sqrt(inv.m[2] * inv.m[2] + inv.m[6] * inv.m[6] + inv.m[10] * inv.m[10]);
        if (!(r > 0))
            return;
    }
    const scene_vertex *v = ip->scene->verts + ip->prim_first;
    const double *m = inv.m;
    for (uint32_t i = 0; i < n; i++) {
        /* In scalars, and no division by an r of 1: an array stored and
         * read back, and three divisions, were most of this loop's time. */
        const float *cn = v[i].normal;
        double e0 = cn[0] * m[0] + cn[1] * m[1] + cn[2] * m[2];
        double e1 = cn[0] * m[4] + cn[1] * m[5] + cn[2] * m[6];
        double e2 = cn[0] * m[8] + cn[1] * m[9] + cn[2] * m[10];
        if (r != 1)
            e0 /= r, e1 /= r, e2 /= r;
        double len2 = e0 * e0 + e1 * e1 + e2 * e2;
        if (fabs(len2 - 1) > 2e-3) {
            interp_note(ip, DIAG_NOTE_NORMALS);
            return;
        }
    }
}

static void end_primitive_body(interp *ip)
{
    scene *s = ip->scene;
    const gl_attribs *a = &ip->st.a;
    ip->in_begin = false;
    ip->prim_plain = 0;
    if (ip->prim_skip || !s)
        return;
    if (s->nverts < ip->prim_first)
        return; /* the pool was cleared under us (cannot happen: Clear is refused in Begin) */
    uint32_t n = (uint32_t)(s->nverts - ip->prim_first);
    GLenum mode = ip->prim_mode;
    if (n == 0)
        return;
    interp_blend_end(ip, n);
    interp_fog_behind_check(ip, n);
    assembly as;
    memset(&as, 0, sizeof as);
    as.ip = ip;
    as.s = s;
    as.base = (uint32_t)ip->prim_first;
    as.painter = ip->painter;
    /* of one colour, whichever segment shows is the same: no step (a
     * draw of thousands, stroke text, would use up the painter's range) */
    as.step = (mode == GL_LINES || mode == GL_LINE_STRIP || mode == GL_LINE_LOOP) &&
              !prim_one_colour(ip);
    as.flat = a->lighting.shade_model == GL_FLAT;
    as.first = a->lighting.provoking == GL_FIRST_VERTEX_CONVENTION;
    as.swap = a->polygon.front_face == GL_CW;
    as.line_smooth = a->caps[INTERP_CAP_LINE_SMOOTH];
    as.stipple = interp_stipple_on(ip);
    /* Stippled lines are cut as Mesa cuts them (interp_stipple.c); the
     * edges of outlined polygons restart the pattern where Mesa's own
     * triangles begin, which the translator does not follow. */
    if (as.stipple && ip->prim_mode > GL_LINE_STRIP &&
        (a->polygon.mode[0] == GL_LINE || a->polygon.mode[1] == GL_LINE))
        interp_note(ip, DIAG_NOTE_STIPPLE);
    as.point_sprite = a->caps[INTERP_CAP_POINT_SPRITE];
    as.point_smooth = a->caps[INTERP_CAP_POINT_SMOOTH] && !as.point_sprite;
    as.line_width = a->line.width;
    as.point_size = a->point.size;
    as.point_params = interp_point_params_set(a);
    /* Mesa splits quads along v1-v3 in a list, and when drawn from an
     * index array (tests/programs/conf_arrays_quad_split.c). */
    as.list_quads = ip->list_depth > (ip->list_ce ? 1 : 0) || ip->prim_indexed;
    as.alpha_test = interp_alpha_testing(ip);
    for (uint32_t i = 0; i < n && !as.check_bad; i++)
        if (!vertex_ok(&s->verts[as.base + i]))
            as.check_bad = true;

    if (mode <= GL_LINE_STRIP) {
        if (mode != GL_POINTS)
            interp_lines_textured(ip);
        if (ip->prim_in_eye)
            vertices_to_eye(ip, n);
        as.check_bad = true;
        assemble_lines(&as, mode, n);
        s->nverts = ip->prim_first; /* lines and points keep no pool vertices */
        return;
    }

    bool cull = a->caps[INTERP_CAP_CULL_FACE];
    GLenum cm = a->polygon.cull_mode;
    as.cull_front = cull && (cm == GL_FRONT || cm == GL_FRONT_AND_BACK);
    as.cull_back = cull && (cm == GL_BACK || cm == GL_FRONT_AND_BACK);
    /* Back faces may need GL's lighting (interp_relit.c). */
    as.facing = cull || a->polygon.mode[0] != a->polygon.mode[1] || interp_relit_wanted(ip) ||
                ip->stencil.two_side || ip->stencil.tri_faces != 3;
    if (as.facing && !compute_clip(ip, n)) {
        s->failed = true;
        return;
    }
    if (mode == GL_QUADS && !as.list_quads)
        as.list_quads = crosses_view_volume(ip, n);
    interp_proj_painter_prims(ip, mode, n);
    if (ip->prim_in_eye) {
        vertices_to_eye(ip, n);
        as.check_bad = true;
    }
    ip->prim_tex_from1 = false;
    gl_material vmat_saved[2];
    bool vmat = interp_vmat_end(ip, n, vmat_saved);
    ip->mip_pending = false;
    ip->mip_defer = true;
    scene_look look = interp_current_look(ip);
    if (vmat)
        interp_vmat_restore(ip, vmat_saved);
    if (ip->prim_tex_from1)
        for (size_t i = 0; i < n; i++) {
            scene_vertex *v = &s->verts[ip->prim_first + i];
            memcpy(v->tex, v->tex1, sizeof v->tex);
        }
    if (look.lit)
        check_normals(ip, n);
    mat4 id = mat4_identity();
    as.mesh = scene_mesh_for(s, ip->prim_in_eye ? &id : &ip->prim_to_eye, ip->prim_in_eye, &look);
    as.fog_split = ip->fog_split;
    as.fill_checks = ip->stencil.write || ip->stencil.only || as.alpha_test || as.fog_split;
    as.look = &look;
    as.to_eye = ip->prim_in_eye ? &id : &ip->prim_to_eye;
    as.in_eye = ip->prim_in_eye;
    size_t first_tri = s->ntris;
    /* the split reads relit_over, the colours' peak */
    if (look.texture >= 0 || (look.lit && interp_relit_wanted(ip) && interp_relit_may_saturate(ip)))
        interp_relit_flush(ip);
    as.relit = interp_relit_split(ip, &look);
    if (as.relit && as.relit != INTERP_RELIT_PROBE && !interp_relit_need_clear(ip, n))
        as.relit = 0;
    /* Outlined faces lit: GL lights their vertices (one-sided lighting;
     * interp_relit.c keeps what that needs; under two-sided lighting its
     * colours are the back faces'). */
    if (look.lit && (a->polygon.mode[0] != GL_FILL || a->polygon.mode[1] != GL_FILL)) {
        if (interp_relit_wanted(ip) && !a->lighting.two_side) {
            interp_relit_flush(ip);
            as.lit_edges = ip->relit_made >= n && ip->relit_col;
        }
        if (!as.lit_edges)
            interp_note(ip, DIAG_NOTE_LIT_OUTLINE);
    }
    bool filled = !as.check_bad && a->polygon.mode[0] == GL_FILL;
    if (filled && !as.facing && !as.relit)
        assemble_filled(&as, mode, n);
    else if (!(filled && as.facing && a->polygon.mode[1] == GL_FILL &&
               as.relit != INTERP_RELIT_PROBE && assemble_facing(&as, mode, n)))
        assemble_polygons(&as, mode, n);
    if (as.relit && as.relit != INTERP_RELIT_PROBE && ip->nrelit_tris > 0) {
        if (interp_relit_vertices(ip, n)) {
            ip->prim_relit = true;
            scene_look gl_look = interp_current_look(ip);
            ip->prim_relit = false;
            as.mesh = scene_mesh_for(s, ip->prim_in_eye ? &id : &ip->prim_to_eye, ip->prim_in_eye,
                                     &gl_look);
            as.copy = ip->relit_copy;
            as.look = &gl_look;
            for (size_t k = 0; k < ip->nrelit_tris; k++) {
                const uint32_t *t = ip->relit_tris[k];
                fill_tri(&as, t[0], t[1], t[2], t[3]);
            }
        }
    }
    interp_relit_done(ip);
    interp_tex_mip_check(ip, first_tri);
    if (look.lit)
        interp_gouraud_check(ip, first_tri);
    if (a->polygon.mode[0] == GL_LINE || a->polygon.mode[1] == GL_LINE)
        interp_lines_textured(ip);
}

static void end_primitive(interp *ip)
{
    end_primitive_body(ip);
    interp_point_sprites_end(ip);
}

void interp_end(interp *ip, const rgl_cmd *cmd)
{
    (void)cmd;
    if (!ip->in_begin) {
        interp_bad_op(ip, "glEnd without glBegin");
        return;
    }
    end_primitive(ip);
    ip->prim_color_sum = ip->prim_fog_vertex = false;
}

bool interp_prim_begin(interp *ip, GLenum mode)
{
    interp_begin_mode(ip, mode);
    return !ip->prim_skip;
}

void interp_prim_end(interp *ip)
{
    if (ip->in_begin)
        end_primitive(ip);
    ip->prim_color_sum = ip->prim_fog_vertex = false;
}

void interp_abort_begin(interp *ip)
{
    if (!ip->in_begin)
        return;
    ip->in_begin = false;
    ip->prim_plain = 0;
    ip->prim_fx = false;
    ip->prim_color_sum = ip->prim_fog_vertex = false;
    if (ip->scene && !ip->prim_skip && ip->scene->nverts >= ip->prim_first)
        ip->scene->nverts = ip->prim_first;
}

/* glRect(x1, y1, x2, y2) is Begin(POLYGON), (x1,y1) (x2,y1) (x2,y2)
 * (x1,y2), End (GL 1.x 2.9). */
void interp_rect(interp *ip, const rgl_cmd *cmd)
{
    double v[4];
    if (cmd->nargs == 2) { /* the vector forms: two arrays of two */
        v[0] = rgl_arg_f(&cmd->arg[0], 0);
        v[1] = rgl_arg_f(&cmd->arg[0], 1);
        v[2] = rgl_arg_f(&cmd->arg[1], 0);
        v[3] = rgl_arg_f(&cmd->arg[1], 1);
    } else {
        for (int i = 0; i < 4; i++)
            v[i] = arg_num(&cmd->arg[i]);
    }
    interp_begin_mode(ip, GL_POLYGON);
    if (!ip->prim_skip) {
        interp_add_vertex(ip, v[0], v[1], 0, 1);
        interp_add_vertex(ip, v[2], v[1], 0, 1);
        interp_add_vertex(ip, v[2], v[3], 0, 1);
        interp_add_vertex(ip, v[0], v[3], 0, 1);
    }
    end_primitive(ip);
}
