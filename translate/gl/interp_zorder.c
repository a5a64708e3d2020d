/* interp_zorder.c: whether draw order without a depth test can change a
 * pixel of the frame (NOTE_DEPTH).
 *
 * Where a draw is made without a depth test (or with GL_ALWAYS), OpenGL
 * shows it over what was drawn before; where a draw writes no depth (no
 * depth test, or glDepthMask(GL_FALSE)), whatever comes later shows over it
 * if it passes the depth buffer's test. A ray tracer shows the nearest
 * surface along each ray. The painter's shift (interp_prim.c) moves each
 * such draw a little toward the camera, so that draws in one plane show in
 * draw order; draws truly apart show nearest first. The two agree on a pixel
 * unless two primitives cover it where one of them is such a draw and the
 * later is not the nearer there.
 *
 * So each draw opens a run (its depth mode and where the scene's pools
 * stood: interp_zorder_draw), and at the frame's end, when a run drew
 * without depth test or depth writes, every pair of primitives that overlap
 * on screen, one of them of such a run, is checked in the scene as the ray
 * tracer sees it: the footprints' intersection, clipped to the image, and
 * along each ray through it the later nearer (the ray parameter of each
 * plane at the intersection's corners: t is a monotonic function of the
 * window position over a convex region, so the corners decide). Two
 * primitives of one unlit, untextured, opaque colour may show in either
 * order. If a pair fails, the note is said at the later draw; otherwise it
 * is held, with why. When the runs lie apart in depth in their order
 * (2D drawings: each draw a painter's step nearer), only pairs within a run
 * are checked, and a run whose primitives step nearer one by one only
 * within each step; other pairs are found through a grid of the image.
 * Past a bound of work or primitives the note is said, unchecked. A depth
 * function other than GL_LESS, GL_LEQUAL or GL_ALWAYS is said at once
 * (docs/mapping.md section 31).
 */
#include "interp_internal.h"

#include <math.h>
#include <string.h>

#include "talloc.h"

enum { ZP_TRIS, ZP_LINES, ZP_POINTS, ZP_SOLIDS, ZP_INSTANCES, ZP_COUNT };

#define ZF_LATER_WINS 1u /* no depth test, or GL_ALWAYS: shows over what came before */
#define ZF_NO_WRITE 2u   /* writes no depth: what comes later shows over it */

/* Bounds on the check, a few tenths of a second at most: past them the
 * note is said unchecked. */
#define ZORDER_MAX_ITEMS (1u << 18)
#define ZORDER_MAX_CELLS (1u << 22) /* grid entries: an item in each cell it covers */
#define ZORDER_MAX_PAIRS 4000000u
#define ZORDER_GRID 64 /* cells across the image's longer side */

typedef struct zrun {
    size_t start[ZP_COUNT]; /* the scene's pool sizes when the run began */
    uint8_t flags;
    uint64_t cmd_index, cmd_offset; /* the draw's command, for the note */
    const char *cmd_name;
} zrun;

struct interp_zorder {
    zrun *runs;
    size_t n, cap;
    bool special; /* a run of the frame has flags */
    uint32_t generation; /* the scene's when the last run began */
};

void interp_zorder_free(interp *ip)
{
    if (!ip->zorder)
        return;
    tr_free(ip->zorder->runs);
    tr_free(ip->zorder);
    ip->zorder = NULL;
}

void interp_zorder_begin_frame(interp *ip)
{
    if (ip->zorder) {
        ip->zorder->n = 0;
        ip->zorder->special = false;
    }
}

static void pool_sizes(const scene *s, size_t out[ZP_COUNT])
{
    out[ZP_TRIS] = s->ntris;
    out[ZP_LINES] = s->nlines;
    out[ZP_POINTS] = s->npoints;
    out[ZP_SOLIDS] = s->nsolids;
    out[ZP_INSTANCES] = s->ninstances;
}

void interp_zorder_draw(interp *ip)
{
    const gl_attribs *a = &ip->st.a;
    scene *s = ip->scene;
    if (!s)
        return;
    bool test = a->caps[INTERP_CAP_DEPTH_TEST];
    GLenum f = a->depth.func;
    if (test && f != GL_LESS && f != GL_LEQUAL && f != GL_ALWAYS) {
        interp_note(ip, DIAG_NOTE_DEPTH); /* GL_GREATER and its kin: not drawn in order at all */
        return;
    }
    uint8_t flags = (uint8_t)((!test || f == GL_ALWAYS ? ZF_LATER_WINS : 0) |
                              (!test || !a->depth.mask ? ZF_NO_WRITE : 0));
    struct interp_zorder *z = ip->zorder;
    if (!z) {
        if (!flags)
            return; /* nothing drawn out of depth order yet: no run needed */
        z = ip->zorder = tr_realloc(NULL, sizeof *z);
        if (!z) {
            s->failed = true;
            return;
        }
        memset(z, 0, sizeof *z);
    }
    if (z->n > 0 && !flags && !z->runs[z->n - 1].flags && z->generation == s->generation)
        return; /* depth-tested draws in a row: one run */
    /* Two runs: the first holds what the frame drew before, depth-tested
     * (runs are kept only once a draw needs one). */
    if (tr_grow((void **)&z->runs, &z->cap, z->n + 2, sizeof *z->runs) != 0) {
        s->failed = true;
        return;
    }
    if (z->n == 0) {
        memset(&z->runs[0], 0, sizeof z->runs[0]);
        z->n = 1;
    }
    zrun *r = &z->runs[z->n++];
    pool_sizes(s, r->start);
    r->flags = flags;
    r->cmd_index = ip->cmd ? ip->cmd->index : 0;
    r->cmd_offset = ip->cmd ? ip->cmd->offset : 0;
    r->cmd_name = ip->cmd && ip->cmd->info ? ip->cmd->info->name : NULL;
    z->special |= flags != 0;
    z->generation = s->generation;
}

/* ---- Primitives as the ray tracer sees them ---------------------------------------- */

#define ZMAX_CORNERS 6 /* a quad cut by the eye plane has 5 */

typedef struct zitem {
    double box[4];      /* x0, y0, x1, y1 in pixels from the image centre */
    double poly[ZMAX_CORNERS][2]; /* the footprint, convex, np corners */
    double plane[4];    /* planar: n . X = d over camera coordinates X */
    double tmin, tmax;  /* the ray parameter over its corners */
    float lo[4], hi[4]; /* its colours' range, when keyed (nothing else varies them) */
    uint32_t run;
    uint8_t pool, flags, np;
    bool planar, keyed, whole; /* whole: covers the image, at any depth */
} zitem;

typedef struct zctx {
    const scene *s;
    const scene_camera *cam;
    double w, h;
    zitem *it;
    size_t n, cap;
    bool over; /* more primitives than ZORDER_MAX_ITEMS */
} zctx;

/* Window position (pixels from the image centre, as scene_camera_project)
 * of camera coordinates X, in front of the camera. */
static void window_of(const zctx *c, const double X[3], double out[2])
{
    double t = c->cam->kind != SCENE_CAMERA_ORTHOGRAPHIC ? X[0] : 1;
    out[0] = X[1] / t * c->w;
    out[1] = X[2] / t * c->h;
}

/* The ray parameter of item it's plane at window point (x, y), or NAN. */
static double plane_t(const zctx *c, const zitem *it, double x, double y)
{
    const double *p = it->plane;
    double u = x / c->w, v = y / c->h, t;
    if (c->cam->kind != SCENE_CAMERA_ORTHOGRAPHIC) {
        double den = p[0] + p[1] * u + p[2] * v;
        t = p[3] / den;
    } else {
        t = (p[3] - p[1] * u - p[2] * v) / p[0];
    }
    return isfinite(t) ? t : NAN;
}

static zitem *item_new(zctx *c, uint32_t run, uint8_t pool, uint8_t flags)
{
    if (c->n >= ZORDER_MAX_ITEMS) {
        c->over = true;
        return NULL;
    }
    if (tr_grow((void **)&c->it, &c->cap, c->n + 1, sizeof *c->it) != 0) {
        c->over = true;
        return NULL;
    }
    zitem *it = &c->it[c->n++];
    memset(it, 0, sizeof *it);
    it->run = run;
    it->pool = pool;
    it->flags = flags;
    return it;
}

/* Fills it's footprint, box, depth range and plane from np (at most 4)
 * eye-space corners (a convex polygon in order; planar when `planar`). A
 * polygon reaching behind a perspective camera is cut at a hair in front
 * of its eye, where the camera still sees it. */
static void item_corners(const zctx *c, zitem *it, const double (*p)[3], int np, bool planar)
{
    double X[4][3], cut[ZMAX_CORNERS][3];
    double tmax = 0;
    for (int k = 0; k < np; k++) {
        if (!scene_camera_coords(c->cam, p[k], X[k])) {
            it->whole = true;
            return;
        }
        tmax = fmax(tmax, X[k][0]);
    }
    int n = 0;
    if (c->cam->kind != SCENE_CAMERA_ORTHOGRAPHIC) {
        double eps = 1e-9 * tmax;
        if (!(tmax > 0)) {
            it->np = 0; /* wholly behind the eye: nothing seen */
            it->box[0] = it->box[1] = INFINITY;
            it->box[2] = it->box[3] = -INFINITY;
            return;
        }
        for (int k = 0; k < np; k++) {
            const double *a = X[k], *b = X[(k + 1) % np];
            bool ain = a[0] > eps, bin = b[0] > eps;
            if (ain)
                memcpy(cut[n++], a, sizeof cut[0]);
            if (ain != bin) {
                double f = (eps - a[0]) / (b[0] - a[0]);
                for (int j = 0; j < 3; j++)
                    cut[n][j] = a[j] + f * (b[j] - a[j]);
                n++;
            }
        }
    } else {
        memcpy(cut, X, (size_t)np * sizeof X[0]);
        n = np;
    }
    it->np = (uint8_t)n;
    it->tmin = INFINITY;
    it->tmax = -INFINITY;
    for (int k = 0; k < n; k++) {
        window_of(c, cut[k], it->poly[k]);
        it->tmin = fmin(it->tmin, cut[k][0]);
        it->tmax = fmax(it->tmax, cut[k][0]);
        if (!isfinite(it->poly[k][0]) || !isfinite(it->poly[k][1])) {
            it->whole = true;
            return;
        }
    }
    if (n < 3) {
        it->np = 0;
        it->box[0] = it->box[1] = INFINITY;
        it->box[2] = it->box[3] = -INFINITY;
        return;
    }
    it->box[0] = it->box[2] = it->poly[0][0];
    it->box[1] = it->box[3] = it->poly[0][1];
    for (int k = 1; k < n; k++) {
        it->box[0] = fmin(it->box[0], it->poly[k][0]);
        it->box[1] = fmin(it->box[1], it->poly[k][1]);
        it->box[2] = fmax(it->box[2], it->poly[k][0]);
        it->box[3] = fmax(it->box[3], it->poly[k][1]);
    }
    if (!planar || np < 3)
        return;
    double e1[3], e2[3], nv[3];
    for (int k = 0; k < 3; k++) {
        e1[k] = X[1][k] - X[0][k];
        e2[k] = X[2][k] - X[0][k];
    }
    nv[0] = e1[1] * e2[2] - e1[2] * e2[1];
    nv[1] = e1[2] * e2[0] - e1[0] * e2[2];
    nv[2] = e1[0] * e2[1] - e1[1] * e2[0];
    double d = nv[0] * X[0][0] + nv[1] * X[0][1] + nv[2] * X[0][2];
    if (!(fabs(nv[0]) + fabs(nv[1]) + fabs(nv[2]) > 0) || !isfinite(d))
        return;
    memcpy(it->plane, nv, sizeof nv);
    it->plane[3] = d;
    it->planar = true;
}

static void apply(const mat4 *m, const float in[3], double out[3])
{
    double p[4] = {in[0], in[1], in[2], 1}, o[4];
    mat4_apply(m, p, o);
    double w = o[3] != 0 ? o[3] : 1;
    for (int k = 0; k < 3; k++)
        out[k] = o[k] / w;
}

/* The one colour a look and vertex colours show everywhere, when nothing
 * (light, texture, fog, blending) varies it. */
static bool look_plain(const scene_look *lk)
{
    return !lk->lit && lk->texture < 0 && lk->texture1 < 0 && lk->blend == SCENE_BLEND_OPAQUE &&
           !lk->fog && lk->alpha_test == SCENE_ALPHA_OFF;
}

static bool look_invisible(const scene_look *lk)
{
    return lk->blend == SCENE_BLEND_INVISIBLE || lk->alpha_test == SCENE_ALPHA_NEVER;
}

/* Widens it's colour range by c (first: starts it). */
static void key_colour(zitem *it, const float c[4], bool first)
{
    for (int k = 0; k < 4; k++) {
        it->lo[k] = first ? c[k] : fminf(it->lo[k], c[k]);
        it->hi[k] = first ? c[k] : fmaxf(it->hi[k], c[k]);
    }
    it->keyed = true;
}

/* Whether a and b show colours within 1/255 of each other everywhere:
 * whichever of them shows, the pixel is the same to a level of 8 bits. */
static bool same_colour(const zitem *a, const zitem *b)
{
    if (!a->keyed || !b->keyed)
        return false;
    for (int k = 0; k < 4; k++)
        if (fmaxf(a->hi[k], b->hi[k]) - fminf(a->lo[k], b->lo[k]) > 1.0f / 255 + 1e-6f)
            return false;
    return true;
}

static void add_tri(zctx *c, const scene_mesh *m, const mat4 *to_eye, const scene_tri *t,
                    uint32_t run, uint8_t pool, uint8_t flags)
{
    if (look_invisible(&m->look))
        return;
    zitem *it = item_new(c, run, pool, flags);
    if (!it)
        return;
    double p[3][3];
    for (int k = 0; k < 3; k++) {
        const float *v = c->s->verts[t->v[k]].pos;
        if (m->in_eye)
            for (int j = 0; j < 3; j++)
                p[k][j] = v[j];
        else
            apply(to_eye, v, p[k]);
    }
    item_corners(c, it, (const double(*)[3])p, 3, true);
    if (look_plain(&m->look)) {
        if (m->look.flat) {
            key_colour(it, c->s->verts[t->provoking].color, true);
        } else {
            for (int k = 0; k < 3; k++)
                key_colour(it, c->s->verts[t->v[k]].color, k == 0);
        }
    }
}

/* The mesh of triangle i, from mesh *mi on (meshes hold triangles in order). */
static const scene_mesh *mesh_of(const scene *s, size_t i, size_t *mi)
{
    while (*mi < s->nmeshes &&
           i >= s->meshes[*mi].first_tri + s->meshes[*mi].tri_count)
        (*mi)++;
    if (*mi >= s->nmeshes || i < s->meshes[*mi].first_tri)
        return NULL;
    return &s->meshes[*mi];
}

static void add_line(zctx *c, const scene_line *l, uint32_t run, uint8_t flags)
{
    zitem *it = item_new(c, run, ZP_LINES, flags);
    if (!it)
        return;
    double p[4][3];
    for (int k = 0; k < 3; k++) {
        p[0][k] = l->p[0][k] + l->half[0][k];
        p[1][k] = l->p[1][k] + l->half[1][k];
        p[2][k] = l->p[1][k] - l->half[1][k];
        p[3][k] = l->p[0][k] - l->half[0][k];
    }
    item_corners(c, it, (const double(*)[3])p, 4, true);
    bool opaque = true;
    for (int k = 0; k < 4; k++)
        opaque = opaque && l->color[k][3] >= 1;
    for (int k = 0; k < 4 && opaque; k++)
        key_colour(it, l->color[k], k == 0);
}

static void add_point(zctx *c, const scene_point *pt, uint32_t run, uint8_t flags)
{
    zitem *it = item_new(c, run, ZP_POINTS, flags);
    if (!it)
        return;
    double p[4][3];
    static const int sr[4] = {-1, 1, 1, -1}, su[4] = {-1, -1, 1, 1};
    for (int i = 0; i < 4; i++)
        for (int k = 0; k < 3; k++)
            p[i][k] = pt->p[k] + sr[i] * pt->right[k] + su[i] * pt->up[k];
    item_corners(c, it, (const double(*)[3])p, 4, true);
    if (pt->color[3] >= 1)
        key_colour(it, pt->color, true);
}

/* A solid by the box around it: not planar, its depth a range. */
static void add_solid(zctx *c, const scene_solid *so, uint32_t run, uint8_t flags)
{
    if (look_invisible(&so->look))
        return;
    zitem *it = item_new(c, run, ZP_SOLIDS, flags);
    if (!it)
        return;
    const double *q = so->params;
    double lo[3], hi[3];
    switch (so->kind) {
    case SCENE_SOLID_BOX:
        for (int k = 0; k < 3; k++)
            lo[k] = -(hi[k] = fabs(q[k]));
        break;
    case SCENE_SOLID_CONE: {
        double r = fmax(fabs(q[0]), fabs(q[1]));
        lo[0] = lo[1] = -r;
        hi[0] = hi[1] = r;
        lo[2] = fmin(0, q[2]);
        hi[2] = fmax(0, q[2]);
        break;
    }
    case SCENE_SOLID_TORUS: {
        double r = fabs(q[0]) + fabs(q[1]);
        lo[0] = lo[1] = -r;
        hi[0] = hi[1] = r;
        lo[2] = -(hi[2] = fabs(q[1]));
        break;
    }
    case SCENE_SOLID_DISC:
        lo[0] = lo[1] = -(hi[0] = hi[1] = fabs(q[0]));
        lo[2] = hi[2] = 0;
        break;
    case SCENE_SOLID_TEAPOT: /* freeglut's teapot lies within 2 sizes of its origin */
        for (int k = 0; k < 3; k++)
            lo[k] = -(hi[k] = 2 * fabs(q[0]));
        break;
    default: /* SPHERE */
        for (int k = 0; k < 3; k++)
            lo[k] = -(hi[k] = fabs(q[0]));
        break;
    }
    it->tmin = INFINITY;
    it->tmax = -INFINITY;
    it->box[0] = it->box[1] = INFINITY;
    it->box[2] = it->box[3] = -INFINITY;
    for (int i = 0; i < 8; i++) {
        float v[3] = {(float)(i & 1 ? hi[0] : lo[0]), (float)(i & 2 ? hi[1] : lo[1]),
                      (float)(i & 4 ? hi[2] : lo[2])};
        double e[3], X[3], o[2];
        apply(&so->to_eye, v, e);
        if (!scene_camera_coords(c->cam, e, X) ||
            (c->cam->kind != SCENE_CAMERA_ORTHOGRAPHIC && !(X[0] > 0))) {
            it->whole = true; /* reaching behind the eye: taken as everywhere */
            return;
        }
        window_of(c, X, o);
        it->box[0] = fmin(it->box[0], o[0]);
        it->box[1] = fmin(it->box[1], o[1]);
        it->box[2] = fmax(it->box[2], o[0]);
        it->box[3] = fmax(it->box[3], o[1]);
        it->tmin = fmin(it->tmin, X[0]);
        it->tmax = fmax(it->tmax, X[0]);
    }
    double bx[4][2] = {{it->box[0], it->box[1]}, {it->box[2], it->box[1]},
                       {it->box[2], it->box[3]}, {it->box[0], it->box[3]}};
    memcpy(it->poly, bx, sizeof bx);
    it->np = 4;
    if (look_plain(&so->look) && so->color[3] >= 1)
        key_colour(it, so->color, true);
}

/* A display-list instance: its prototype's triangles, placed. */
static void add_instance(zctx *c, const scene_instance *in, uint32_t run, uint8_t flags)
{
    const scene *s = c->s;
    const scene_proto *pr = &s->protos[in->proto];
    for (size_t k = 0; k < pr->nmeshes && pr->first_mesh + k < s->nmeshes && !c->over; k++) {
        const scene_mesh *m = &s->meshes[pr->first_mesh + k];
        mat4 to_eye = mat4_mul(&in->to_eye, &m->to_eye);
        for (size_t t = 0; t < m->tri_count && m->first_tri + t < s->ntris && !c->over; t++)
            add_tri(c, m, &to_eye, &s->tris[m->first_tri + t], run, ZP_INSTANCES, flags);
    }
}

/* The run whose triangles hold triangle i (ranges [start, end) per run), or
 * `fallback`. */
static uint32_t run_of_tri(const struct interp_zorder *z, const size_t *end, size_t i,
                           uint32_t fallback)
{
    for (size_t r = 0; r < z->n; r++)
        if (i >= z->runs[r].start[ZP_TRIS] && i < end[r * ZP_COUNT + ZP_TRIS])
            return (uint32_t)r;
    return fallback;
}

/* Every primitive of the scene, run by run, in draw order within a pool. */
static void collect(zctx *c, const struct interp_zorder *z)
{
    const scene *s = c->s;
    size_t total[ZP_COUNT];
    pool_sizes(s, total);
    /* A run's range ends where a later run starts: pools truncated since
     * (a display-list call shared, an accumulation pass dropped) are taken
     * over by the runs after. */
    size_t *end = tr_realloc(NULL, (z->n ? z->n : 1) * ZP_COUNT * sizeof *end);
    if (!end) {
        c->over = true;
        return;
    }
    for (int p = 0; p < ZP_COUNT; p++) {
        size_t lim = total[p];
        for (size_t r = z->n; r-- > 0;) {
            end[r * ZP_COUNT + p] = lim;
            lim = z->runs[r].start[p] < lim ? z->runs[r].start[p] : lim;
        }
    }
    size_t mi = 0;
    for (size_t r = 0; r < z->n && !c->over; r++) {
        const zrun *run = &z->runs[r];
        uint8_t fl = run->flags;
        size_t a = run->start[ZP_TRIS], b = end[r * ZP_COUNT + ZP_TRIS];
        for (size_t i = a; i < b && !c->over; i++) {
            const scene_mesh *m = mesh_of(s, i, &mi);
            if (m && !m->proto)
                add_tri(c, m, &m->to_eye, &s->tris[i], (uint32_t)r, ZP_TRIS, fl);
        }
        const size_t *lo = run->start;
        for (size_t i = lo[ZP_LINES]; i < end[r * ZP_COUNT + ZP_LINES] && !c->over; i++)
            add_line(c, &s->lines[i], (uint32_t)r, fl);
        for (size_t i = lo[ZP_POINTS]; i < end[r * ZP_COUNT + ZP_POINTS] && !c->over; i++)
            add_point(c, &s->points[i], (uint32_t)r, fl);
        for (size_t i = lo[ZP_SOLIDS]; i < end[r * ZP_COUNT + ZP_SOLIDS] && !c->over; i++)
            add_solid(c, &s->solids[i], (uint32_t)r, fl);
        for (size_t i = lo[ZP_INSTANCES]; i < end[r * ZP_COUNT + ZP_INSTANCES] && !c->over; i++) {
            const scene_instance *in = &s->instances[i];
            if (in->proto >= s->nprotos)
                continue;
            /* The call that made a prototype becomes its first instance
             * only at the second call (interp_list.c, group_promote): it
             * takes the run of the call's own triangles, the prototype's. */
            uint32_t at = (uint32_t)r;
            bool first = true;
            for (size_t k = 0; k < i && first; k++)
                first = s->instances[k].proto != in->proto;
            const scene_proto *pr = &s->protos[in->proto];
            if (first && pr->nmeshes && pr->first_mesh < s->nmeshes)
                at = run_of_tri(z, end, s->meshes[pr->first_mesh].first_tri, at);
            add_instance(c, in, at, z->runs[at].flags);
        }
    }
    tr_free(end);
}

/* ---- Pairs ------------------------------------------------------------------------ */

/* Clips the convex polygon in (n corners) by the half-plane left of the
 * directed edge a -> b (b - a turned counter-clockwise): out, its count. */
static int clip_edge(const double (*in)[2], int n, const double a[2], const double b[2],
                     double (*out)[2])
{
    int m = 0;
    double ex = b[0] - a[0], ey = b[1] - a[1];
    for (int i = 0; i < n; i++) {
        const double *p = in[i], *q = in[(i + 1) % n];
        double sp = ex * (p[1] - a[1]) - ey * (p[0] - a[0]);
        double sq = ex * (q[1] - a[1]) - ey * (q[0] - a[0]);
        if (sp >= 0) {
            out[m][0] = p[0];
            out[m][1] = p[1];
            m++;
        }
        if ((sp >= 0) != (sq >= 0)) {
            double f = sp / (sp - sq);
            out[m][0] = p[0] + f * (q[0] - p[0]);
            out[m][1] = p[1] + f * (q[1] - p[1]);
            m++;
        }
    }
    return m;
}

static double poly_area(const double (*p)[2], int n)
{
    double a = 0;
    for (int i = 0; i < n; i++) {
        const double *u = p[i], *v = p[(i + 1) % n];
        a += u[0] * v[1] - v[0] * u[1];
    }
    return a / 2;
}

/* Whether the convex polygon p holds a pixel centre (centres at
 * -w/2 + i + 1/2): row by row, the polygon's span at the row's height. */
static bool holds_centre(const zctx *c, const double (*p)[2], int n)
{
    double y0 = INFINITY, y1 = -INFINITY;
    for (int i = 0; i < n; i++) {
        y0 = fmin(y0, p[i][1]);
        y1 = fmax(y1, p[i][1]);
    }
    double ox = -c->w / 2 + 0.5, oy = -c->h / 2 + 0.5;
    for (double y = ceil(y0 - oy) + oy; y < y1; y++) {
        if (y <= y0)
            continue;
        double lo = INFINITY, hi = -INFINITY;
        for (int i = 0; i < n; i++) {
            const double *a = p[i], *b = p[(i + 1) % n];
            if ((a[1] <= y) == (b[1] <= y))
                continue; /* the edge does not cross the row */
            double x = a[0] + (y - a[1]) / (b[1] - a[1]) * (b[0] - a[0]);
            lo = fmin(lo, x);
            hi = fmax(hi, x);
        }
        double k = ceil(lo - ox);
        if (lo <= hi && k + ox == lo)
            k++; /* on the edge: outside */
        if (k + ox < hi)
            return true;
    }
    return false;
}

/* The intersection of a's and b's footprints within the image, into out
 * (counter-clockwise); its corner count, 0 when it covers no pixel centre. */
static int overlap(const zctx *c, const zitem *a, const zitem *b, double (*out)[2])
{
    double hw = c->w / 2, hh = c->h / 2;
    double buf[2][4 + 2 * ZMAX_CORNERS][2];
    int n = 4;
    double img[4][2] = {{-hw, -hh}, {hw, -hh}, {hw, hh}, {-hw, hh}};
    memcpy(buf[0], img, sizeof img);
    int cur = 0;
    for (int pass = 0; pass < 2 && n > 0; pass++) {
        const zitem *it = pass ? b : a;
        double q[ZMAX_CORNERS][2];
        int m = it->np;
        memcpy(q, it->poly, sizeof q);
        if (poly_area((const double(*)[2])q, m) < 0)
            for (int i = 0; i < m / 2; i++) {
                double t0 = q[i][0], t1 = q[i][1];
                q[i][0] = q[m - 1 - i][0];
                q[i][1] = q[m - 1 - i][1];
                q[m - 1 - i][0] = t0;
                q[m - 1 - i][1] = t1;
            }
        for (int e = 0; e < m && n > 0; e++) {
            n = clip_edge((const double(*)[2])buf[cur], n, q[e], q[(e + 1) % m], buf[!cur]);
            cur = !cur;
            if (n > 4 + 2 * ZMAX_CORNERS)
                n = 4 + 2 * ZMAX_CORNERS; /* convex clips of convex polygons grow no further */
        }
    }
    if (n < 3)
        return 0;
    double area = poly_area((const double(*)[2])buf[cur], n);
    if (!(area > 1e-9))
        return 0;
    if (!holds_centre(c, (const double(*)[2])buf[cur], n))
        return 0;
    memcpy(out, buf[cur], (size_t)n * sizeof *out);
    return n;
}

/* The ray parameters of it over the intersection poly: its range. */
static void t_range(const zctx *c, const zitem *it, const double (*poly)[2], int n, double *lo,
                    double *hi)
{
    if (!it->planar) {
        *lo = it->tmin;
        *hi = it->tmax;
        return;
    }
    *lo = INFINITY;
    *hi = -INFINITY;
    for (int i = 0; i < n; i++) {
        double t = plane_t(c, it, poly[i][0], poly[i][1]);
        if (!isfinite(t)) {
            *lo = -INFINITY;
            *hi = INFINITY;
            return;
        }
        *lo = fmin(*lo, t);
        *hi = fmax(*hi, t);
    }
}

/* Tolerance on ray parameters: float noise, well under the painter's step
 * (a factor 5e-5, or 1e-3 eye units, interp_prim.c). */
static double tol(double t) { return 2e-6 * fabs(t) + 1e-12; }

/* Whether b, drawn after a, is nearer than a wherever both cover a pixel
 * centre (or they cannot differ there). unordered: which came first is
 * unknown. Lines and points are the rectangles of the pixels GL lights
 * (interp_lines.c), their edges between pixel centres: they meet where GL
 * lights a pixel twice, and nowhere else. */
static bool pair_ok(const zctx *c, const zitem *a, const zitem *b, bool unordered)
{
    if (!a->whole && !b->whole &&
        (a->box[2] <= b->box[0] || b->box[2] <= a->box[0] || a->box[3] <= b->box[1] ||
         b->box[3] <= a->box[1]))
        return true;
    if (same_colour(a, b))
        return true;
    if (a->whole || b->whole)
        return false;
    double poly[4 + 2 * ZMAX_CORNERS][2];
    int n = overlap(c, a, b, poly);
    if (n == 0)
        return true;
    if (unordered)
        return false;
    if (a->planar && b->planar) {
        for (int i = 0; i < n; i++) {
            double ta = plane_t(c, a, poly[i][0], poly[i][1]);
            double tb = plane_t(c, b, poly[i][0], poly[i][1]);
            if (!(tb < ta - tol(ta)))
                return false;
        }
        return true;
    }
    double alo, ahi, blo, bhi;
    t_range(c, a, (const double(*)[2])poly, n, &alo, &ahi);
    t_range(c, b, (const double(*)[2])poly, n, &blo, &bhi);
    return bhi < alo - tol(alo);
}

typedef struct zgrid {
    int gw, gh;
    double cell;
    uint32_t *first; /* gw * gh + 1 offsets into idx */
    uint32_t *idx;   /* per cell, item indices in draw order */
} zgrid;

/* The cells of box b (x0, y0, x1, y1), clamped to the grid; an empty span
 * (x1 < x0) when it lies outside the image. */
static void cell_span(const zctx *c, const zgrid *g, const double *b, bool whole, int o[4])
{
    if (whole) {
        o[0] = o[1] = 0;
        o[2] = g->gw - 1;
        o[3] = g->gh - 1;
        return;
    }
    double ox = -c->w / 2, oy = -c->h / 2;
    double v[4] = {floor((b[0] - ox) / g->cell), floor((b[1] - oy) / g->cell),
                   floor((b[2] - ox) / g->cell), floor((b[3] - oy) / g->cell)};
    int lim[4] = {g->gw - 1, g->gh - 1, g->gw - 1, g->gh - 1};
    for (int k = 0; k < 4; k++)
        o[k] = !(v[k] > 0) ? 0 : v[k] > lim[k] ? lim[k] : (int)v[k];
    if (!(b[2] >= ox && b[3] >= oy && b[0] <= -ox && b[1] <= -oy))
        o[2] = o[0] - 1;
}

/* The grid of items sub[0..n-1] (in draw order). False past the bounds. */
static bool grid_build(const zctx *c, const uint32_t *sub, size_t n, zgrid *g)
{
    double longer = fmax(c->w, c->h);
    g->cell = fmax(8, ceil(longer / ZORDER_GRID));
    g->gw = (int)ceil(c->w / g->cell);
    g->gh = (int)ceil(c->h / g->cell);
    g->gw = g->gw < 1 ? 1 : g->gw;
    g->gh = g->gh < 1 ? 1 : g->gh;
    size_t ncell = (size_t)g->gw * (size_t)g->gh;
    g->idx = NULL;
    g->first = tr_realloc(NULL, (ncell + 1) * sizeof *g->first);
    if (!g->first)
        return false;
    memset(g->first, 0, (ncell + 1) * sizeof *g->first);
    uint64_t total = 0;
    for (size_t i = 0; i < n; i++) {
        int o[4];
        const zitem *it = &c->it[sub[i]];
        cell_span(c, g, it->box, it->whole, o);
        for (int y = o[1]; y <= o[3] && o[0] <= o[2]; y++)
            for (int x = o[0]; x <= o[2]; x++)
                g->first[(size_t)y * (size_t)g->gw + (size_t)x + 1]++;
        total += o[0] <= o[2] ? (uint64_t)(o[2] - o[0] + 1) * (uint64_t)(o[3] - o[1] + 1) : 0;
        if (total > ZORDER_MAX_CELLS)
            return false;
    }
    for (size_t k = 0; k < ncell; k++)
        g->first[k + 1] += g->first[k];
    g->idx = tr_realloc(NULL, (total ? total : 1) * sizeof *g->idx);
    uint32_t *fill = tr_realloc(NULL, ncell * sizeof *fill);
    if (!g->idx || !fill) {
        tr_free(fill);
        return false;
    }
    memcpy(fill, g->first, ncell * sizeof *fill);
    for (size_t i = 0; i < n; i++) {
        int o[4];
        const zitem *it = &c->it[sub[i]];
        cell_span(c, g, it->box, it->whole, o);
        for (int y = o[1]; y <= o[3] && o[0] <= o[2]; y++)
            for (int x = o[0]; x <= o[2]; x++)
                g->idx[fill[(size_t)y * (size_t)g->gw + (size_t)x]++] = sub[i];
    }
    tr_free(fill);
    return true;
}

static bool special(const zitem *it) { return it->flags != 0; }

/* The result of a check: ok, a pair that may differ (its later item), or
 * too much to check. */
enum { ZORDER_OK, ZORDER_DIFFERS, ZORDER_UNCHECKED };

/* Checks every pair of sub[0..n-1] (item indices in draw order) that
 * overlaps on screen and needs it (the earlier writes no depth, or the
 * later wins), within the work bound *work. */
/* Whether pair (a, b), a the earlier of sub's order, needs a check, and
 * which is earlier in truth (a first instance may come back to an earlier
 * run): *pa before *pb, unordered when the order is not known. */
static bool pair_needed(const zitem **pa, const zitem **pb, bool *unordered)
{
    const zitem *a = *pa, *b = *pb;
    if (a->run > b->run) {
        *pa = b;
        *pb = a;
        a = *pa;
        b = *pb;
    }
    *unordered = a->run == b->run && a->pool != b->pool;
    return *unordered ? (a->flags | b->flags) != 0
                      : (a->flags & ZF_NO_WRITE) || (b->flags & ZF_LATER_WINS);
}

static int check_pairs(const zctx *c, const uint32_t *sub, size_t n, uint64_t *work,
                       size_t *culprit)
{
    if (n <= 32) { /* a draw of a few primitives: every pair, no grid */
        for (size_t i = 0; i < n; i++)
            for (size_t k = i + 1; k < n; k++) {
                const zitem *a = &c->it[sub[i]], *b = &c->it[sub[k]];
                bool unordered;
                if (++*work > ZORDER_MAX_PAIRS)
                    return ZORDER_UNCHECKED;
                if (!pair_needed(&a, &b, &unordered) || pair_ok(c, a, b, unordered))
                    continue;
                *culprit = (size_t)(b - c->it);
                return ZORDER_DIFFERS;
            }
        return ZORDER_OK;
    }
    zgrid g;
    if (!grid_build(c, sub, n, &g)) {
        tr_free(g.first);
        tr_free(g.idx);
        return ZORDER_UNCHECKED;
    }
    int result = ZORDER_OK;
    size_t ncell = (size_t)g.gw * (size_t)g.gh;
    /* The pairs a cell costs, bounded before any is looked at. */
    uint64_t est = 0;
    for (size_t cell = 0; cell < ncell; cell++) {
        uint64_t ns = 0, nl = g.first[cell + 1] - g.first[cell];
        for (uint32_t k = g.first[cell]; k < g.first[cell + 1]; k++)
            ns += special(&c->it[g.idx[k]]);
        est += ns * nl;
    }
    if (*work + est > ZORDER_MAX_PAIRS)
        result = ZORDER_UNCHECKED;
    for (size_t cell = 0; cell < ncell && result == ZORDER_OK; cell++) {
        int cx = (int)(cell % (size_t)g.gw), cy = (int)(cell / (size_t)g.gw);
        for (uint32_t si = g.first[cell]; si < g.first[cell + 1] && result == ZORDER_OK; si++) {
            uint32_t s = g.idx[si];
            if (!special(&c->it[s]))
                continue;
            for (uint32_t ti = g.first[cell]; ti < g.first[cell + 1]; ti++) {
                uint32_t t = g.idx[ti];
                (*work)++;
                if (t == s || (special(&c->it[t]) && t < s))
                    continue; /* that pair is taken from t's side */
                const zitem *a = &c->it[s < t ? s : t], *b = &c->it[s < t ? t : s];
                bool unordered;
                if (!pair_needed(&a, &b, &unordered))
                    continue;
                /* Each pair once: in the cell of its boxes' common corner. */
                if (!a->whole && !b->whole) {
                    double corner[4] = {fmax(a->box[0], b->box[0]), fmax(a->box[1], b->box[1])};
                    corner[2] = corner[0];
                    corner[3] = corner[1];
                    int o[4];
                    cell_span(c, &g, corner, false, o);
                    if (o[0] <= o[2] && (o[0] != cx || o[1] != cy))
                        continue;
                } else if (a->whole && b->whole && cell != 0) {
                    continue;
                }
                if (!pair_ok(c, a, b, unordered)) {
                    *culprit = (size_t)(b - c->it);
                    result = ZORDER_DIFFERS;
                    break;
                }
            }
        }
    }
    tr_free(g.first);
    tr_free(g.idx);
    return result;
}

/* Whether the runs lie apart in depth in their order wherever order counts:
 * each run that wins over what came before is nearer than all of it, each
 * that writes no depth farther than all that follows (ray parameters over
 * whole runs: on a ray through both, the later is then the nearer). Then
 * only pairs within a run remain to check (2D drawings: each draw a
 * painter's step nearer than the one before). */
static bool runs_apart(const zctx *c, size_t nruns, const uint32_t *first, const uint32_t *order)
{
    double *lo = tr_realloc(NULL, 2 * (nruns ? nruns : 1) * sizeof *lo);
    if (!lo)
        return false;
    double *hi = lo + nruns;
    uint8_t fl_any = 0;
    for (size_t r = 0; r < nruns; r++) {
        lo[r] = INFINITY;
        hi[r] = -INFINITY;
        for (uint32_t k = first[r]; k < first[r + 1]; k++) {
            const zitem *it = &c->it[order[k]];
            if (it->whole) {
                lo[r] = -INFINITY;
                hi[r] = INFINITY;
            } else if (it->np) {
                lo[r] = fmin(lo[r], it->tmin);
                hi[r] = fmax(hi[r], it->tmax);
            }
            fl_any |= it->flags;
        }
    }
    bool ok = true;
    double before = INFINITY; /* the nearest of the earlier runs */
    for (size_t r = 0; r < nruns && ok; r++) {
        bool wins = first[r] < first[r + 1] && (c->it[order[first[r]]].flags & ZF_LATER_WINS);
        if (wins && lo[r] <= hi[r] && before < INFINITY && !(hi[r] < before - tol(before)))
            ok = false;
        if (lo[r] <= hi[r])
            before = fmin(before, lo[r]);
    }
    double after = -INFINITY; /* the farthest of the later runs */
    for (size_t r = nruns; r-- > 0 && ok;) {
        bool nowrite = first[r] < first[r + 1] && (c->it[order[first[r]]].flags & ZF_NO_WRITE);
        if (nowrite && lo[r] <= hi[r] && after > -INFINITY && !(after < lo[r] - tol(lo[r])))
            ok = false;
        if (lo[r] <= hi[r])
            after = fmax(after, hi[r]);
    }
    tr_free(lo);
    return ok;
}

/* One run's items sub[0..n-1], when its primitives step nearer one by one
 * (a GL_TRIANGLES or GL_QUADS batch without a depth test: each primitive a
 * painter's step of its own): groups of consecutive items of one depth (a
 * quad's two triangles), each group nearer than all before it, and the
 * pairs within a group. ZORDER_UNCHECKED: not so (the caller checks every
 * pair of the run). */
static int run_stepped(const zctx *c, const uint32_t *sub, size_t n, uint64_t *work,
                       size_t *culprit)
{
    double before = INFINITY, glo = 0, ghi = 0;
    size_t g0 = 0;
    for (size_t i = 0; i <= n; i++) {
        const zitem *it = i < n ? &c->it[sub[i]] : NULL;
        if (it && (it->whole || it->pool != c->it[sub[0]].pool))
            return ZORDER_UNCHECKED;
        if (it && !it->np)
            continue;
        if (it && i > g0 && it->tmin <= ghi + tol(ghi) && it->tmax >= glo - tol(glo)) {
            glo = fmin(glo, it->tmin);
            ghi = fmax(ghi, it->tmax);
            continue;
        }
        if (i > g0) { /* close the group [g0, i) */
            if (before < INFINITY && !(ghi < before - tol(before)))
                return ZORDER_UNCHECKED;
            if (i - g0 > 32)
                return ZORDER_UNCHECKED;
            int res = i - g0 >= 2 ? check_pairs(c, sub + g0, i - g0, work, culprit) : ZORDER_OK;
            if (res != ZORDER_OK)
                return res;
            before = fmin(before, glo);
        }
        g0 = i;
        if (it) {
            glo = it->tmin;
            ghi = it->tmax;
        }
    }
    return ZORDER_OK;
}

/* Every pair that can differ in the frame: the runs' items grouped by run
 * (a counting sort: instances may come back to earlier runs); when the
 * runs lie apart, each run's own pairs, else all of them. */
static int check_frame(const zctx *c, size_t nruns, size_t *culprit)
{
    uint32_t *first = tr_realloc(NULL, (nruns + 1) * sizeof *first);
    uint32_t *order = tr_realloc(NULL, (c->n ? c->n : 1) * sizeof *order);
    int res = ZORDER_UNCHECKED;
    if (!first || !order)
        goto done;
    memset(first, 0, (nruns + 1) * sizeof *first);
    for (size_t i = 0; i < c->n; i++)
        first[c->it[i].run + 1]++;
    for (size_t r = 0; r < nruns; r++)
        first[r + 1] += first[r];
    {
        uint32_t *fill = tr_realloc(NULL, (nruns ? nruns : 1) * sizeof *fill);
        if (!fill)
            goto done;
        memcpy(fill, first, nruns * sizeof *fill);
        for (size_t i = 0; i < c->n; i++)
            order[fill[c->it[i].run]++] = (uint32_t)i;
        tr_free(fill);
    }
    uint64_t work = 0;
    if (!runs_apart(c, nruns, first, order)) {
        res = check_pairs(c, order, c->n, &work, culprit);
        goto done;
    }
    res = ZORDER_OK;
    for (size_t r = 0; r < nruns && res == ZORDER_OK; r++) {
        uint32_t n = first[r + 1] - first[r];
        if (n < 2 || !c->it[order[first[r]]].flags)
            continue;
        res = n > 32 ? run_stepped(c, order + first[r], n, &work, culprit) : ZORDER_UNCHECKED;
        if (res == ZORDER_UNCHECKED)
            res = check_pairs(c, order + first[r], n, &work, culprit);
    }
done:
    tr_free(first);
    tr_free(order);
    return res;
}

/* ---- The frame's decision -------------------------------------------------------- */

/* The note (held for a reason why, or said: NULL), naming the run's draw
 * as if said when it was made. */
static void note_at_run(interp *ip, const zrun *r, const char *why)
{
    interp_note_cmd(ip, DIAG_NOTE_DEPTH, r->cmd_name != NULL, r->cmd_index, r->cmd_name,
                    r->cmd_offset, why);
}

void interp_zorder_end_frame(interp *ip)
{
    struct interp_zorder *z = ip->zorder;
    scene *s = ip->scene;
    if (!z || !z->special || !s || interp_note_said(ip, DIAG_NOTE_DEPTH))
        return;
    const zrun *first = &z->runs[0];
    for (size_t r = 0; r < z->n; r++)
        if (z->runs[r].flags) {
            first = &z->runs[r];
            break;
        }
    if (!s->have_camera || s->camera.width < 1 || s->camera.height < 1) {
        note_at_run(ip, first, NULL);
        return;
    }
    zctx c;
    memset(&c, 0, sizeof c);
    c.s = s;
    c.cam = &s->camera;
    c.w = s->camera.width;
    c.h = s->camera.height;
    collect(&c, z);
    size_t culprit = 0;
    int res = c.over ? ZORDER_UNCHECKED : check_frame(&c, z->n, &culprit);
    if (res == ZORDER_DIFFERS)
        note_at_run(ip, &z->runs[c.it[culprit].run], NULL);
    else if (res == ZORDER_UNCHECKED)
        note_at_run(ip, first, NULL);
    else
        note_at_run(ip, first,
                    "where draws without a depth test or depth writes overlap others on "
                    "screen, the later is the nearer, or both show one colour");
    tr_free(c.it);
}
