/* interp_shape.c: GLU quadrics and GLUT solids (issue 5).
 *
 * A shape whose GL image a POV-Ray solid reproduces exactly (filled, both
 * polygon modes GL_FILL, no culling that would show its inside, untextured,
 * not faceted under lighting) becomes that solid (scene_solid), placed by
 * the modelview in GL's axis conventions: GLU's and GLUT's spheres, cones
 * and cylinders along +z from z=0, the torus in the xy plane around z, the
 * cube centred. Otherwise the interpreter draws the shape itself through
 * the ordinary primitive path, with the vertices, normals and texture
 * coordinates GLU 9 and freeglut 3 give it, so culling, polygon mode, flat
 * shading, lines (wire forms, GLU_LINE, GLU_SILHOUETTE) and points
 * (GLU_POINT) come out as GL draws them. The Platonic solids are always
 * meshes: their faces are flat. The teapot is Newell's patches (teapot.h).
 * docs/mapping.md lists the rules.
 */
#include "interp_internal.h"

#include <string.h>

#include "teapot.h"

#include <GL/glu.h>

/* ---- Quadric objects ------------------------------------------------------------ */

static const interp_quadric quadric_default = {0, GLU_FILL, GLU_SMOOTH, GLU_OUTSIDE, false};

static interp_quadric *quadric_slot(interp *ip, uint32_t id, bool create)
{
    if (id == 0)
        return NULL;
    interp_quadric *free_slot = NULL;
    for (int i = 0; i < INTERP_QUADRICS; i++) {
        if (ip->st.quadrics[i].id == id)
            return &ip->st.quadrics[i];
        if (!free_slot && ip->st.quadrics[i].id == 0)
            free_slot = &ip->st.quadrics[i];
    }
    if (!create)
        return NULL;
    if (!free_slot) /* more live quadrics than slots: reuse one by id */
        free_slot = &ip->st.quadrics[id % INTERP_QUADRICS];
    *free_slot = quadric_default;
    free_slot->id = id;
    return free_slot;
}

static interp_quadric quadric_get(interp *ip, uint32_t id)
{
    const interp_quadric *q = quadric_slot(ip, id, false);
    return q ? *q : quadric_default;
}

static uint32_t quad_id(const rgl_cmd *cmd) { return (uint32_t)cmd->arg[0].v.u; }

void interp_newquadric(interp *ip, const rgl_cmd *cmd)
{
    interp_quadric *q = quadric_slot(ip, quad_id(cmd), true);
    if (q) {
        uint32_t id = q->id;
        *q = quadric_default;
        q->id = id;
    }
}

void interp_deletequadric(interp *ip, const rgl_cmd *cmd)
{
    interp_quadric *q = quadric_slot(ip, quad_id(cmd), false);
    if (q)
        memset(q, 0, sizeof *q);
}

/* GLU reports a bad value through the quadric's error callback, not as a
 * GL error: the call is ignored with a diagnostic. */
static void quadric_set(interp *ip, const rgl_cmd *cmd, int what)
{
    GLenum v = arg_enum(cmd, 1);
    bool ok;
    switch (what) {
    case 0: ok = v == GLU_FILL || v == GLU_LINE || v == GLU_SILHOUETTE || v == GLU_POINT; break;
    case 1: ok = v == GLU_NONE || v == GLU_FLAT || v == GLU_SMOOTH; break;
    default: ok = v == GLU_OUTSIDE || v == GLU_INSIDE; break;
    }
    if (!ok) {
        interp_diag(ip, DIAG_IGNORED, "GLU_INVALID_ENUM 0x%x: quadric unchanged", (unsigned)v);
        return;
    }
    interp_quadric *q = quadric_slot(ip, quad_id(cmd), true);
    if (!q)
        return;
    if (what == 0)
        q->draw_style = v;
    else if (what == 1)
        q->normals = v;
    else
        q->orientation = v;
}

void interp_quadricdrawstyle(interp *ip, const rgl_cmd *cmd) { quadric_set(ip, cmd, 0); }
void interp_quadricnormals(interp *ip, const rgl_cmd *cmd) { quadric_set(ip, cmd, 1); }
void interp_quadricorientation(interp *ip, const rgl_cmd *cmd) { quadric_set(ip, cmd, 2); }

void interp_quadrictexture(interp *ip, const rgl_cmd *cmd)
{
    interp_quadric *q = quadric_slot(ip, quad_id(cmd), true);
    if (q)
        q->texture = cmd->arg[1].v.u != 0;
}

/* ---- Emitting primitives ---------------------------------------------------------- */

/* How the vertices of a shape carry normals and texture coordinates. */
typedef struct shape_style {
    GLenum normals;   /* GLU_NONE, GLU_FLAT, GLU_SMOOTH */
    bool inside;      /* GLU_INSIDE: normals and front faces point in */
    bool texture;     /* generate texture coordinates */
    bool triangles;   /* cells as two triangles split along (i,j)-(i+1,j+1),
                         as freeglut's strips split them (polygon mode
                         GL_LINE shows the split), else as GLU's quads */
    bool clockwise;   /* front faces wound clockwise about the normal
                         (freeglut's teapot) */
} shape_style;

static void set_normal(interp *ip, const double n[3])
{
    for (int k = 0; k < 3; k++)
        ip->st.a.current.normal[k] = (float)n[k];
}

static void set_tex(interp *ip, double s, double t)
{
    float *tc = ip->st.a.current.texcoord;
    tc[0] = (float)s;
    tc[1] = (float)t;
    tc[2] = 0;
    tc[3] = 1;
}

static void put_vertex(interp *ip, const double p[3])
{
    if (ip->in_begin && !ip->prim_skip)
        interp_add_vertex(ip, p[0], p[1], p[2], 1);
}

/* A point of a parametric surface: position, outward normal (unit), and
 * texture coordinates. */
typedef struct surf_point {
    double p[3], n[3], t[2];
} surf_point;

typedef void (*surf_fn)(const void *ctx, int i, int j, surf_point *out);

static void emit_point(interp *ip, const shape_style *st, const surf_point *sp)
{
    if (st->normals != GLU_NONE) {
        double n[3] = {sp->n[0], sp->n[1], sp->n[2]};
        if (st->inside)
            n[0] = -n[0], n[1] = -n[1], n[2] = -n[2];
        set_normal(ip, n);
    }
    if (st->texture)
        set_tex(ip, sp->t[0], sp->t[1]);
    put_vertex(ip, sp->p);
}

/* Fills the grid of cells [0, ni) x [0, nj) as quads, each wound so that
 * its front faces along the surface normal (outside) or against it
 * (inside), as GLU and freeglut wind theirs. Flat normals: one per quad,
 * its geometric normal. */
static void grid_fill(interp *ip, const shape_style *st, surf_fn f, const void *ctx, int ni, int nj)
{
    interp_prim_begin(ip, st->triangles ? GL_TRIANGLES : GL_QUADS);
    for (int j = 0; j < nj; j++)
        for (int i = 0; i < ni; i++) {
            surf_point c[4];
            f(ctx, i, j, &c[0]);
            f(ctx, i + 1, j, &c[1]);
            f(ctx, i + 1, j + 1, &c[2]);
            f(ctx, i, j + 1, &c[3]);
            /* Geometric normal from the diagonals (degenerate edges at
             * poles and apexes leave the diagonals intact). */
            double d1[3], d2[3], g[3], avg = 0;
            for (int k = 0; k < 3; k++) {
                d1[k] = c[2].p[k] - c[0].p[k];
                d2[k] = c[3].p[k] - c[1].p[k];
            }
            g[0] = d1[1] * d2[2] - d1[2] * d2[1];
            g[1] = d1[2] * d2[0] - d1[0] * d2[2];
            g[2] = d1[0] * d2[1] - d1[1] * d2[0];
            for (int v = 0; v < 4; v++)
                avg += g[0] * c[v].n[0] + g[1] * c[v].n[1] + g[2] * c[v].n[2];
            bool reverse = ((avg < 0) != st->inside) != st->clockwise;
            if (st->normals == GLU_FLAT) {
                double len = sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
                double s = (avg < 0 ? -1 : 1) / (len > 0 ? len : 1);
                for (int v = 0; v < 4; v++)
                    for (int k = 0; k < 3; k++)
                        c[v].n[k] = g[k] * s;
            }
            if (st->triangles) {
                static const int fwd[6] = {0, 1, 2, 0, 2, 3}, rev[6] = {2, 1, 0, 3, 2, 0};
                for (int v = 0; v < 6; v++)
                    emit_point(ip, st, &c[reverse ? rev[v] : fwd[v]]);
            } else {
                for (int v = 0; v < 4; v++)
                    emit_point(ip, st, &c[reverse ? 3 - v : v]);
            }
        }
    interp_prim_end(ip);
}

/* GLU's own primitives for a filled surface with smooth or no normals: a
 * GL_QUAD_STRIP per row j in [j0, j1) through i = 0..ni, the vertex
 * (i, j + 1) before (i, j) when upper_first, as gluSphere, gluCylinder
 * and gluPartialDisk send them. GL splits each strip quad along the
 * diagonal from its first vertex, which Gouraud shading shows
 * (--vertex-lighting), and a flat-shaded quad takes its last vertex's
 * colour. */
static void glu_strips(interp *ip, const shape_style *st, surf_fn f, const void *ctx, int ni,
                       int j0, int j1, bool upper_first)
{
    for (int j = j0; j < j1; j++) {
        interp_prim_begin(ip, GL_QUAD_STRIP);
        for (int i = 0; i <= ni; i++) {
            surf_point a, b;
            f(ctx, i, upper_first ? j + 1 : j, &a);
            f(ctx, i, upper_first ? j : j + 1, &b);
            emit_point(ip, st, &a);
            emit_point(ip, st, &b);
        }
        interp_prim_end(ip);
    }
}

/* GLU's GL_TRIANGLE_FAN from the apex f(0, japex) around row j, i from
 * ni down to 0 (descending) or up. */
static void glu_fan(interp *ip, const shape_style *st, surf_fn f, const void *ctx, int ni,
                    int japex, int j, bool descending)
{
    surf_point sp;
    interp_prim_begin(ip, GL_TRIANGLE_FAN);
    f(ctx, 0, japex, &sp);
    emit_point(ip, st, &sp);
    for (int k = 0; k <= ni; k++) {
        f(ctx, descending ? ni - k : k, j, &sp);
        emit_point(ip, st, &sp);
    }
    interp_prim_end(ip);
}

/* A line strip (or loop) through f(i, j) for i in [i0, i1] at fixed j
 * (along_i) or for j in [i0, i1] at fixed i. */
static void grid_line(interp *ip, const shape_style *st, surf_fn f, const void *ctx, GLenum mode,
                      bool along_i, int fixed, int from, int to)
{
    interp_prim_begin(ip, mode);
    for (int k = from; k <= to; k++) {
        surf_point sp;
        if (along_i)
            f(ctx, k, fixed, &sp);
        else
            f(ctx, fixed, k, &sp);
        emit_point(ip, st, &sp);
    }
    interp_prim_end(ip);
}

/* A trace may ask for any number of slices and stacks; GL would draw them
 * all, but a few bytes must not cost minutes or gigabytes here. Above
 * these many facets, for one shape or for a frame's shapes together, the
 * tessellated shape is skipped (exact solids are unaffected). A 512 x 512
 * sphere is within the first. */
#define SHAPE_MAX_FACETS (1u << 18)
#define FRAME_MAX_SHAPE_FACETS (1u << 21)

static bool tess_ok(interp *ip, const char *shape, int ni, int nj)
{
    uint64_t n = (uint64_t)(ni > 0 ? ni : 0) * (uint64_t)(nj > 0 ? nj : 0);
    if (n > SHAPE_MAX_FACETS) {
        interp_diag(ip, DIAG_IGNORED, "%s with %d x %d facets skipped: over the %u RayGL tessellates",
                    shape, ni, nj, SHAPE_MAX_FACETS);
        return false;
    }
    if (ip->shape_facets + n > FRAME_MAX_SHAPE_FACETS) {
        interp_diag(ip, DIAG_IGNORED, "%s skipped: the frame's shapes exceed %u facets", shape,
                    FRAME_MAX_SHAPE_FACETS);
        return false;
    }
    ip->shape_facets += n;
    return true;
}

/* Whether the exact solid shows what GL shows for a filled shape. closed:
 * the surface encloses a volume seen only from outside; faceted: GL's
 * normals are per face. */
static bool exact_ok(interp *ip, bool closed, bool inside, bool faceted)
{
    const gl_attribs *a = &ip->st.a;
    if (a->polygon.mode[0] != GL_FILL || a->polygon.mode[1] != GL_FILL)
        return false;
    if (a->caps[INTERP_CAP_CULL_FACE] &&
        !(closed && !inside && a->polygon.front_face == GL_CCW && a->polygon.cull_mode == GL_BACK))
        return false;
    if (a->caps[INTERP_CAP_LIGHTING] && (faceted || a->lighting.shade_model == GL_FLAT))
        return false;
    if (!ip->prim_relit && interp_vertex_lit(ip))
        return false; /* --vertex-lighting: GL's facets in GL's lit colours */
    if (interp_texture_for_draw(ip) >= 0)
        return false; /* the mesh carries the texture coordinates */
    if (interp_offset_active(ip))
        return false; /* lines drawn over it lie on GL's facets */
    if (interp_stencil_writes(ip) || interp_stencil_faces_differ(ip))
        return false; /* its triangles make the stencil region, or face it */
    return true;
}

/* Adds the solid when exact_ok allowed it. Returns false when the caller
 * must draw the shape as primitives instead. */
static bool emit_solid(interp *ip, scene_solid_kind kind, bool open, double p0, double p1,
                       double p2)
{
    if (!interp_prim_begin(ip, GL_TRIANGLES)) {
        interp_abort_begin(ip);
        return true; /* nothing is drawn either way */
    }
    if (ip->prim_in_eye) { /* a projective or singular transform: vertices carry it */
        interp_abort_begin(ip);
        return false;
    }
    scene_solid *so = scene_add_solid(ip->scene);
    if (so) {
        so->kind = kind;
        so->open = open;
        so->params[0] = p0;
        so->params[1] = p1;
        so->params[2] = p2;
        so->to_eye = ip->prim_to_eye;
        so->look = interp_current_look(ip);
        interp_surface_colour(ip, so->color);
        /* An unlit solid's colour is GL's final one: one fog coordinate
         * and secondary colour for the whole shape (interp_fogsec.c). */
        if (ip->prim_color_sum || ip->prim_fog_vertex)
            interp_fogsec_vertex(ip, so->color);
    }
    interp_abort_begin(ip);
    return true;
}

static bool finite_args(interp *ip, const rgl_cmd *cmd, uint32_t from, uint32_t to)
{
    for (uint32_t k = from; k < to && k < cmd->nargs; k++)
        if (!isfinite(arg_num(&cmd->arg[k]))) {
            interp_diag(ip, DIAG_BAD_NUMBER, "shape size is NaN or infinite: skipped");
            return false;
        }
    return true;
}

/* ---- GLU surfaces --------------------------------------------------------------- */

/* GLU 9 limits slices and stacks to its cache size. */
#define GLU_CACHE 240

typedef struct glu_sphere {
    double r;
    int slices, stacks;
} glu_sphere;

/* GLU's sphere: angle theta_i = 2 pi i / slices around z from +y toward
 * +x, phi_j = pi j / stacks down from +z; s = 1 - i/slices, t = 1 -
 * j/stacks. */
static void glu_sphere_at(const void *ctx, int i, int j, surf_point *o)
{
    const glu_sphere *g = ctx;
    double th = 2 * M_PI * (i % g->slices) / g->slices, ph = M_PI * j / g->stacks;
    double sp = (j == 0 || j == g->stacks) ? 0 : sin(ph), cp = cos(ph);
    o->n[0] = sp * sin(th);
    o->n[1] = sp * cos(th);
    o->n[2] = cp;
    for (int k = 0; k < 3; k++)
        o->p[k] = g->r * o->n[k];
    o->t[0] = 1 - (double)i / g->slices;
    o->t[1] = 1 - (double)j / g->stacks;
}

typedef struct glu_cyl {
    double base, top, height;
    int slices, stacks;
    double nz, nxy; /* normal: (nxy sin, nxy cos, nz) */
} glu_cyl;

static void glu_cyl_at(const void *ctx, int i, int j, surf_point *o)
{
    const glu_cyl *g = ctx;
    double th = 2 * M_PI * (i % g->slices) / g->slices;
    double r = g->base - (g->base - g->top) * j / g->stacks;
    o->p[0] = r * sin(th);
    o->p[1] = r * cos(th);
    o->p[2] = g->height * j / g->stacks;
    o->n[0] = g->nxy * sin(th);
    o->n[1] = g->nxy * cos(th);
    o->n[2] = g->nz;
    o->t[0] = 1 - (double)i / g->slices;
    o->t[1] = (double)j / g->stacks;
}

typedef struct glu_disk {
    double inner, outer, start, sweep; /* radians */
    int slices, loops;
    bool full;
} glu_disk;

/* j counts loops from the outer edge in. */
static void glu_disk_at(const void *ctx, int i, int j, surf_point *o)
{
    const glu_disk *g = ctx;
    int ii = g->full ? i % g->slices : i;
    double th = g->start + g->sweep * ii / g->slices;
    double r = g->outer - (g->outer - g->inner) * j / g->loops;
    o->p[0] = r * sin(th);
    o->p[1] = r * cos(th);
    o->p[2] = 0;
    o->n[0] = o->n[1] = 0;
    o->n[2] = 1;
    double tr = r / g->outer / 2;
    o->t[0] = tr * sin(th) + 0.5;
    o->t[1] = tr * cos(th) + 0.5;
}

static shape_style quadric_style(const interp_quadric *q)
{
    shape_style st = {q->normals, q->orientation == GLU_INSIDE, q->texture, false, false};
    return st;
}

static bool glu_faceted(const interp_quadric *q) { return q->normals != GLU_SMOOTH; }

void interp_glusphere(interp *ip, const rgl_cmd *cmd)
{
    if (!ip->scene || !finite_args(ip, cmd, 1, 2))
        return;
    interp_quadric q = quadric_get(ip, quad_id(cmd));
    glu_sphere g = {arg_num(&cmd->arg[1]), (int)cmd->arg[2].v.i, (int)cmd->arg[3].v.i};
    if (g.slices >= GLU_CACHE)
        g.slices = GLU_CACHE - 1;
    if (g.stacks >= GLU_CACHE)
        g.stacks = GLU_CACHE - 1;
    if (g.slices < 2 || g.stacks < 1 || g.r < 0) {
        interp_diag(ip, DIAG_IGNORED, "gluSphere: GLU_INVALID_VALUE");
        return;
    }
    shape_style st = quadric_style(&q);
    switch (q.draw_style) {
    case GLU_FILL:
        if (exact_ok(ip, true, st.inside, glu_faceted(&q)) &&
            emit_solid(ip, SCENE_SOLID_SPHERE, false, g.r, 0, 0))
            return;
        if (st.normals == GLU_FLAT) {
            grid_fill(ip, &st, glu_sphere_at, &g, g.slices, g.stacks);
        } else if (st.texture) {
            glu_strips(ip, &st, glu_sphere_at, &g, g.slices, 0, g.stacks, !st.inside);
        } else { /* the poles as fans: GLU needs no texture coordinates there */
            glu_fan(ip, &st, glu_sphere_at, &g, g.slices, 0, 1, !st.inside);
            glu_fan(ip, &st, glu_sphere_at, &g, g.slices, g.stacks, g.stacks - 1, st.inside);
            glu_strips(ip, &st, glu_sphere_at, &g, g.slices, 1, g.stacks - 1, !st.inside);
        }
        break;
    case GLU_POINT:
        interp_prim_begin(ip, GL_POINTS);
        for (int j = 0; j <= g.stacks; j++)
            for (int i = 0; i < g.slices; i++) {
                surf_point sp;
                glu_sphere_at(&g, i, j, &sp);
                emit_point(ip, &st, &sp);
            }
        interp_prim_end(ip);
        break;
    default: /* GLU_LINE and GLU_SILHOUETTE draw the same for a sphere */
        for (int j = 1; j < g.stacks; j++)
            grid_line(ip, &st, glu_sphere_at, &g, GL_LINE_STRIP, true, j, 0, g.slices);
        for (int i = 0; i < g.slices; i++)
            grid_line(ip, &st, glu_sphere_at, &g, GL_LINE_STRIP, false, i, 0, g.stacks);
        break;
    }
}

void interp_glucylinder(interp *ip, const rgl_cmd *cmd)
{
    if (!ip->scene || !finite_args(ip, cmd, 1, 4))
        return;
    interp_quadric q = quadric_get(ip, quad_id(cmd));
    glu_cyl g = {arg_num(&cmd->arg[1]), arg_num(&cmd->arg[2]), arg_num(&cmd->arg[3]),
                 (int)cmd->arg[4].v.i, (int)cmd->arg[5].v.i, 0, 0};
    if (g.slices >= GLU_CACHE)
        g.slices = GLU_CACHE - 1;
    double dr = g.base - g.top, len = sqrt(dr * dr + g.height * g.height);
    if (g.slices < 2 || g.stacks < 1 || g.base < 0 || g.top < 0 || g.height < 0 || len == 0) {
        interp_diag(ip, DIAG_IGNORED, "gluCylinder: GLU_INVALID_VALUE");
        return;
    }
    g.nz = dr / len;
    g.nxy = g.height / len;
    shape_style st = quadric_style(&q);
    if (q.draw_style != GLU_FILL && !tess_ok(ip, "gluCylinder", g.slices, g.stacks))
        return;
    switch (q.draw_style) {
    case GLU_FILL:
        if (g.height > 0 && exact_ok(ip, false, st.inside, glu_faceted(&q)) &&
            emit_solid(ip, SCENE_SOLID_CONE, true, g.base, g.top, g.height))
            return;
        if (!tess_ok(ip, "gluCylinder", g.slices, g.stacks)) /* GLU caps slices, not stacks */
            break;
        if (st.normals == GLU_FLAT)
            grid_fill(ip, &st, glu_cyl_at, &g, g.slices, g.stacks);
        else
            glu_strips(ip, &st, glu_cyl_at, &g, g.slices, 0, g.stacks, st.inside);
        break;
    case GLU_POINT:
        interp_prim_begin(ip, GL_POINTS);
        for (int i = 0; i < g.slices; i++)
            for (int j = 0; j <= g.stacks; j++) {
                surf_point sp;
                glu_cyl_at(&g, i, j, &sp);
                emit_point(ip, &st, &sp);
            }
        interp_prim_end(ip);
        break;
    default:
        if (q.draw_style == GLU_LINE)
            for (int j = 1; j < g.stacks; j++)
                grid_line(ip, &st, glu_cyl_at, &g, GL_LINE_STRIP, true, j, 0, g.slices);
        grid_line(ip, &st, glu_cyl_at, &g, GL_LINE_STRIP, true, 0, 0, g.slices);
        grid_line(ip, &st, glu_cyl_at, &g, GL_LINE_STRIP, true, g.stacks, 0, g.slices);
        for (int i = 0; i < g.slices; i++)
            grid_line(ip, &st, glu_cyl_at, &g, GL_LINE_STRIP, false, i, 0, g.stacks);
        break;
    }
}

static void glu_disk_draw(interp *ip, const rgl_cmd *cmd, double inner, double outer, int slices,
                          int loops, double start_deg, double sweep_deg)
{
    interp_quadric q = quadric_get(ip, quad_id(cmd));
    if (slices >= GLU_CACHE)
        slices = GLU_CACHE - 1;
    if (slices < 2 || loops < 1 || !(outer > 0) || inner < 0 || inner > outer) {
        interp_diag(ip, DIAG_IGNORED, "gluDisk: GLU_INVALID_VALUE");
        return;
    }
    /* GLU's normalisation of the sweep. */
    if (sweep_deg < -360.0 || sweep_deg > 360.0)
        sweep_deg = 360.0;
    if (sweep_deg < 0) {
        start_deg += sweep_deg;
        sweep_deg = -sweep_deg;
    }
    glu_disk g = {inner, outer, start_deg / 180.0 * M_PI, sweep_deg / 180.0 * M_PI, slices, loops,
                  sweep_deg == 360.0};
    int slices2 = g.full ? slices : slices + 1;
    shape_style st = quadric_style(&q);
    if (!(q.draw_style == GLU_FILL && g.full) && !tess_ok(ip, "gluDisk", slices, loops))
        return; /* GLU caps slices, not loops */
    if (q.normals != GLU_NONE) { /* one normal for the whole disk */
        double n[3] = {0, 0, st.inside ? -1 : 1};
        set_normal(ip, n);
        st.normals = GLU_NONE;
    }
    switch (q.draw_style) {
    case GLU_FILL:
        if (g.full && exact_ok(ip, false, st.inside, false) &&
            emit_solid(ip, SCENE_SOLID_DISC, false, outer, inner, 0))
            return;
        if (!tess_ok(ip, "gluDisk", slices, loops))
            break;
        if (inner == 0) { /* the centre as a fan */
            glu_fan(ip, &st, glu_disk_at, &g, slices, loops, loops - 1, !st.inside);
            glu_strips(ip, &st, glu_disk_at, &g, slices, 0, loops - 1, st.inside);
        } else {
            glu_strips(ip, &st, glu_disk_at, &g, slices, 0, loops, st.inside);
        }
        break;
    case GLU_POINT:
        interp_prim_begin(ip, GL_POINTS);
        for (int i = 0; i < slices2; i++)
            for (int j = 0; j <= loops; j++) {
                surf_point sp;
                glu_disk_at(&g, i, j, &sp);
                emit_point(ip, &st, &sp);
            }
        interp_prim_end(ip);
        break;
    case GLU_LINE:
        if (inner == outer) {
            grid_line(ip, &st, glu_disk_at, &g, GL_LINE_STRIP, true, 0, 0, slices);
            break;
        }
        for (int j = 0; j <= loops; j++)
            grid_line(ip, &st, glu_disk_at, &g, GL_LINE_STRIP, true, j, 0, slices);
        for (int i = 0; i < slices2; i++)
            grid_line(ip, &st, glu_disk_at, &g, GL_LINE_STRIP, false, i, 0, loops);
        break;
    default: /* GLU_SILHOUETTE */
        if (!g.full) {
            grid_line(ip, &st, glu_disk_at, &g, GL_LINE_STRIP, false, 0, 0, loops);
            grid_line(ip, &st, glu_disk_at, &g, GL_LINE_STRIP, false, slices, 0, loops);
        }
        grid_line(ip, &st, glu_disk_at, &g, GL_LINE_STRIP, true, 0, 0, slices);
        if (inner != outer)
            grid_line(ip, &st, glu_disk_at, &g, GL_LINE_STRIP, true, loops, 0, slices);
        break;
    }
}

void interp_gludisk(interp *ip, const rgl_cmd *cmd)
{
    if (!ip->scene || !finite_args(ip, cmd, 1, 3))
        return;
    glu_disk_draw(ip, cmd, arg_num(&cmd->arg[1]), arg_num(&cmd->arg[2]), (int)cmd->arg[3].v.i,
                  (int)cmd->arg[4].v.i, 0, 360);
}

void interp_glupartialdisk(interp *ip, const rgl_cmd *cmd)
{
    if (!ip->scene || !finite_args(ip, cmd, 1, 3) || !finite_args(ip, cmd, 5, 7))
        return;
    glu_disk_draw(ip, cmd, arg_num(&cmd->arg[1]), arg_num(&cmd->arg[2]), (int)cmd->arg[3].v.i,
                  (int)cmd->arg[4].v.i, arg_num(&cmd->arg[5]), arg_num(&cmd->arg[6]));
}

/* ---- GLUT solids ------------------------------------------------------------------ */

/* freeglut 3 draws its shapes from arrays, which leave GL's current normal
 * undefined; a program cannot rely on it, so it is kept as it was. */
typedef struct saved_current {
    float normal[3], texcoord[4];
} saved_current;

static saved_current save_current(const interp *ip)
{
    saved_current s;
    memcpy(s.normal, ip->st.a.current.normal, sizeof s.normal);
    memcpy(s.texcoord, ip->st.a.current.texcoord, sizeof s.texcoord);
    return s;
}

static void restore_current(interp *ip, const saved_current *s)
{
    memcpy(ip->st.a.current.normal, s->normal, sizeof s->normal);
    memcpy(ip->st.a.current.texcoord, s->texcoord, sizeof s->texcoord);
}

static bool is_wire(const rgl_cmd *cmd)
{
    switch (cmd->opcode) {
    case RGL_OP_WireSphere: case RGL_OP_WireCube: case RGL_OP_WireCone: case RGL_OP_WireTorus:
    case RGL_OP_WireTeapot: case RGL_OP_WireDodecahedron: case RGL_OP_WireOctahedron:
    case RGL_OP_WireTetrahedron: case RGL_OP_WireIcosahedron: case RGL_OP_WireCylinder:
    case RGL_OP_WireRhombicDodecahedron:
        return true;
    default:
        return false;
    }
}

static const shape_style glut_style = {GLU_SMOOTH, false, false, true, false};

/* Point pair k (of n round a band) of one of a shape's strips. */
typedef void (*pair_fn)(const void *ctx, int band, int k, surf_point out[2]);

/* freeglut 3 fills its sphere, cone, cylinder and torus with one
 * GL_TRIANGLE_STRIP per band: n pairs of points once round, then the
 * first pair again. The same strips in the same order give GL's split of
 * each cell, its winding, and under GL_FLAT its lighting (the normal of
 * each triangle's last vertex). */
static void glut_strips(interp *ip, pair_fn f, const void *ctx, int bands, int n)
{
    for (int b = 0; b < bands; b++) {
        interp_prim_begin(ip, GL_TRIANGLE_STRIP);
        for (int k = 0; k <= n; k++) {
            surf_point pr[2];
            f(ctx, b, k % n, pr);
            emit_point(ip, &glut_style, &pr[0]);
            emit_point(ip, &glut_style, &pr[1]);
        }
        interp_prim_end(ip);
    }
}

/* freeglut's sphere: theta_j = -2 pi j / slices around z from +x,
 * phi_i = pi i / stacks down from +z. */
typedef struct glut_sphere {
    double r;
    int slices, stacks;
} glut_sphere;

static void glut_sphere_at(const void *ctx, int j, int i, surf_point *o)
{
    const glut_sphere *g = ctx;
    double th = -2 * M_PI * (j % g->slices) / g->slices, ph = M_PI * i / g->stacks;
    double sp = (i == 0 || i == g->stacks) ? 0 : sin(ph);
    o->n[0] = cos(th) * sp;
    o->n[1] = sin(th) * sp;
    o->n[2] = i == g->stacks ? -1 : cos(ph);
    for (int k = 0; k < 3; k++)
        o->p[k] = g->r * o->n[k];
    o->t[0] = o->t[1] = 0;
}

/* Band b lies between levels b and b + 1, the lower point first (the
 * poles are one vertex each, their triangles the strip's every other). */
static void glut_sphere_pair(const void *ctx, int b, int k, surf_point out[2])
{
    glut_sphere_at(ctx, k, b + 1, &out[0]);
    glut_sphere_at(ctx, k, b, &out[1]);
}

void interp_glutsphere(interp *ip, const rgl_cmd *cmd)
{
    if (!ip->scene || !finite_args(ip, cmd, 0, 1))
        return;
    glut_sphere g = {arg_num(&cmd->arg[0]), (int)cmd->arg[1].v.i, (int)cmd->arg[2].v.i};
    if (g.slices <= 0 || g.stacks < 2)
        return; /* freeglut draws nothing */
    saved_current sc = save_current(ip);
    if (!is_wire(cmd)) {
        if (!(exact_ok(ip, true, false, false) &&
              emit_solid(ip, SCENE_SOLID_SPHERE, false, fabs(g.r), 0, 0)) &&
            tess_ok(ip, "glutSolidSphere", g.slices, g.stacks))
            glut_strips(ip, glut_sphere_pair, &g, g.stacks, g.slices);
    } else if (tess_ok(ip, "glutWireSphere", g.slices, g.stacks)) {
        for (int i = 1; i < g.stacks; i++)
            grid_line(ip, &glut_style, glut_sphere_at, &g, GL_LINE_LOOP, true, i, 0, g.slices - 1);
        for (int j = 0; j < g.slices; j++)
            grid_line(ip, &glut_style, glut_sphere_at, &g, GL_LINE_STRIP, false, j, 0, g.stacks);
    }
    restore_current(ip, &sc);
}

/* freeglut's cone and cylinder: level i of stacks (z = i h / stacks),
 * theta_j = -2 pi j / slices from +x. */
typedef struct glut_cyl {
    double base, top, height;
    int slices, stacks;
    double nxy, nz;
} glut_cyl;

static void glut_cyl_at(const void *ctx, int j, int i, surf_point *o)
{
    const glut_cyl *g = ctx;
    double th = -2 * M_PI * (j % g->slices) / g->slices;
    double r = g->base + (g->top - g->base) * i / g->stacks;
    o->p[0] = cos(th) * r;
    o->p[1] = sin(th) * r;
    o->p[2] = g->height * i / g->stacks;
    o->n[0] = cos(th) * g->nxy;
    o->n[1] = sin(th) * g->nxy;
    o->n[2] = g->nz;
    o->t[0] = o->t[1] = 0;
}

/* Band 0 is the base (its centre first), bands 1 .. stacks the side,
 * lower level first; the cylinder's band stacks + 1 its top (centre
 * last). The caps' points carry the caps' normals. */
static void glut_cyl_pair(const void *ctx, int b, int k, surf_point out[2])
{
    const glut_cyl *g = ctx;
    if (b >= 1 && b <= g->stacks) {
        glut_cyl_at(ctx, k, b - 1, &out[0]);
        glut_cyl_at(ctx, k, b, &out[1]);
        return;
    }
    bool base = b == 0;
    surf_point rim, centre = {{0, 0, base ? 0 : g->height}, {0, 0, base ? -1 : 1}, {0, 0}};
    glut_cyl_at(ctx, k, base ? 0 : g->stacks, &rim);
    rim.n[0] = rim.n[1] = 0;
    rim.n[2] = centre.n[2];
    out[base ? 0 : 1] = centre;
    out[base ? 1 : 0] = rim;
}

static void glut_cyl_draw(interp *ip, const rgl_cmd *cmd, glut_cyl *g, bool cone)
{
    saved_current sc = save_current(ip);
    double len = hypot(g->height, g->base - g->top);
    g->nxy = len > 0 ? g->height / len : 1;
    g->nz = len > 0 ? (g->base - g->top) / len : 0;
    if (!is_wire(cmd)) {
        if (!(exact_ok(ip, true, false, false) && g->height > 0 &&
              emit_solid(ip, SCENE_SOLID_CONE, false, g->base, g->top, g->height)) &&
            tess_ok(ip, cone ? "glutSolidCone" : "glutSolidCylinder", g->slices, g->stacks)) {
            glut_strips(ip, glut_cyl_pair, g, g->stacks + (cone ? 1 : 2), g->slices);
        }
    } else if (tess_ok(ip, cone ? "glutWireCone" : "glutWireCylinder", g->slices, g->stacks)) {
        /* Rings: the cone's at levels 0 .. stacks-1, the cylinder's at
         * 0 .. stacks; then one line per slice from bottom to top. */
        int rings = cone ? g->stacks - 1 : g->stacks;
        for (int i = 0; i <= rings; i++)
            grid_line(ip, &glut_style, glut_cyl_at, g, GL_LINE_LOOP, true, i, 0, g->slices - 1);
        interp_prim_begin(ip, GL_LINES);
        for (int j = 0; j < g->slices; j++) {
            surf_point a, b;
            glut_cyl_at(g, j, 0, &a);
            glut_cyl_at(g, j, g->stacks, &b);
            emit_point(ip, &glut_style, &a);
            emit_point(ip, &glut_style, &b);
        }
        interp_prim_end(ip);
    }
    restore_current(ip, &sc);
}

void interp_glutcone(interp *ip, const rgl_cmd *cmd)
{
    if (!ip->scene || !finite_args(ip, cmd, 0, 2))
        return;
    glut_cyl g = {arg_num(&cmd->arg[0]), 0, arg_num(&cmd->arg[1]), (int)cmd->arg[2].v.i,
                  (int)cmd->arg[3].v.i, 0, 0};
    if (g.slices <= 0 || g.stacks < 1)
        return;
    glut_cyl_draw(ip, cmd, &g, true);
}

void interp_glutcylinder(interp *ip, const rgl_cmd *cmd)
{
    if (!ip->scene || !finite_args(ip, cmd, 0, 2))
        return;
    double r = arg_num(&cmd->arg[0]);
    glut_cyl g = {r, r, arg_num(&cmd->arg[1]), (int)cmd->arg[2].v.i, (int)cmd->arg[3].v.i, 0, 0};
    if (g.slices <= 0 || g.stacks < 1)
        return;
    glut_cyl_draw(ip, cmd, &g, false);
}

/* freeglut's torus: ring angle psi_j = 2 pi j / rings around z from +x,
 * tube angle phi_i = -2 pi i / sides. */
typedef struct glut_torus {
    double inner, outer;
    int sides, rings;
} glut_torus;

static void glut_torus_at(const void *ctx, int j, int i, surf_point *o)
{
    const glut_torus *g = ctx;
    double psi = 2 * M_PI * (j % g->rings) / g->rings, phi = -2 * M_PI * (i % g->sides) / g->sides;
    o->p[0] = cos(psi) * (g->outer + cos(phi) * g->inner);
    o->p[1] = sin(psi) * (g->outer + cos(phi) * g->inner);
    o->p[2] = sin(phi) * g->inner;
    o->n[0] = cos(psi) * cos(phi);
    o->n[1] = sin(psi) * cos(phi);
    o->n[2] = sin(phi);
    o->t[0] = o->t[1] = 0;
}

/* Band i runs round the rings between sides i and i + 1. */
static void glut_torus_pair(const void *ctx, int i, int k, surf_point out[2])
{
    glut_torus_at(ctx, k, i, &out[0]);
    glut_torus_at(ctx, k, i + 1, &out[1]);
}

void interp_gluttorus(interp *ip, const rgl_cmd *cmd)
{
    if (!ip->scene || !finite_args(ip, cmd, 0, 2))
        return;
    glut_torus g = {arg_num(&cmd->arg[0]), arg_num(&cmd->arg[1]), (int)cmd->arg[2].v.i,
                    (int)cmd->arg[3].v.i};
    if (g.sides < 2 || g.rings < 2)
        return;
    saved_current sc = save_current(ip);
    if (!is_wire(cmd)) {
        /* POV-Ray's torus is the true one only when the tube does not
         * cross the axis. */
        bool exact = g.inner > 0 && g.outer > g.inner;
        if (!(exact && exact_ok(ip, true, false, false) &&
              emit_solid(ip, SCENE_SOLID_TORUS, false, g.outer, g.inner, 0)) &&
            tess_ok(ip, "glutSolidTorus", g.rings, g.sides))
            glut_strips(ip, glut_torus_pair, &g, g.sides, g.rings);
    } else if (tess_ok(ip, "glutWireTorus", g.rings, g.sides)) {
        for (int j = 0; j < g.rings; j++)
            grid_line(ip, &glut_style, glut_torus_at, &g, GL_LINE_LOOP, false, j, 0, g.sides - 1);
        for (int i = 0; i < g.sides; i++)
            grid_line(ip, &glut_style, glut_torus_at, &g, GL_LINE_LOOP, true, i, 0, g.rings - 1);
    }
    restore_current(ip, &sc);
}

/* ---- Polyhedra ---------------------------------------------------------------------- */

#define POLY_MAX_VERTS 20

typedef struct polyhedron {
    int n;
    double v[POLY_MAX_VERTS][3];
} polyhedron;

/* The vertex sets freeglut 3 uses (radius 1 but for the cube's half side
 * 0.5 and the dodecahedron's sqrt 3). The faces are their convex hull. */
static void polyhedron_for(uint16_t op, polyhedron *ph)
{
    ph->n = 0;
#define ADD(x, y, z)                                   \
    do {                                               \
        double *v_ = ph->v[ph->n++];                   \
        v_[0] = (x), v_[1] = (y), v_[2] = (z);         \
    } while (0)
    switch (op) {
    case RGL_OP_SolidDodecahedron: case RGL_OP_WireDodecahedron: {
        double a = (sqrt(5.0) - 1) / 2, b = (sqrt(5.0) + 1) / 2;
        for (int s = 0; s < 8; s++)
            ADD(s & 1 ? -1 : 1, s & 2 ? -1 : 1, s & 4 ? -1 : 1);
        for (int s = 0; s < 4; s++) {
            double p = s & 1 ? -a : a, q = s & 2 ? -b : b;
            ADD(p, 0, q);
            ADD(0, q, p);
            ADD(q, p, 0);
        }
        break;
    }
    case RGL_OP_SolidIcosahedron: case RGL_OP_WireIcosahedron: {
        double x = 1 / sqrt(5.0), r = 2 / sqrt(5.0);
        ADD(1, 0, 0);
        ADD(-1, 0, 0);
        for (int k = 0; k < 5; k++) {
            double t = 2 * M_PI * k / 5;
            ADD(x, r * cos(t), r * sin(t));
            ADD(-x, -r * cos(t), -r * sin(t));
        }
        break;
    }
    case RGL_OP_SolidOctahedron: case RGL_OP_WireOctahedron:
        for (int k = 0; k < 3; k++) {
            double p[3] = {0, 0, 0};
            p[k] = 1;
            ADD(p[0], p[1], p[2]);
            ADD(-p[0], -p[1], -p[2]);
        }
        break;
    case RGL_OP_SolidTetrahedron: case RGL_OP_WireTetrahedron:
        ADD(1, 0, 0);
        ADD(-1.0 / 3, 2 * sqrt(2.0) / 3, 0);
        ADD(-1.0 / 3, -sqrt(2.0) / 3, sqrt(6.0) / 3);
        ADD(-1.0 / 3, -sqrt(2.0) / 3, -sqrt(6.0) / 3);
        break;
    case RGL_OP_SolidRhombicDodecahedron: case RGL_OP_WireRhombicDodecahedron: {
        double s = sqrt(0.5);
        ADD(0, 0, 1);
        ADD(0, 0, -1);
        for (int k = 0; k < 4; k++) {
            double c = k == 0 ? 1 : k == 2 ? -1 : 0, d = k == 1 ? 1 : k == 3 ? -1 : 0;
            ADD(c * s, d * s, 0.5);
            ADD(c * s, d * s, -0.5);
            ADD((c - d) * s, (c + d) * s, 0);
        }
        break;
    }
    default: /* the cube, size 1 */
        for (int s = 0; s < 8; s++)
            ADD(s & 1 ? -0.5 : 0.5, s & 2 ? -0.5 : 0.5, s & 4 ? -0.5 : 0.5);
        break;
    }
#undef ADD
}

/* Calls face(ctx, idx, n, normal) for each face of the convex hull, its
 * vertices counter-clockwise seen from outside. */
static void polyhedron_faces(const polyhedron *ph, double scale,
                             void (*face)(interp *, const double (*)[3], int, const double *, bool),
                             interp *ip, bool wire)
{
    const double eps = 1e-9;
    for (int a = 0; a < ph->n; a++)
        for (int b = a + 1; b < ph->n; b++)
            for (int c = b + 1; c < ph->n; c++) {
                const double *A = ph->v[a], *B = ph->v[b], *C = ph->v[c];
                double e1[3], e2[3], n[3];
                for (int k = 0; k < 3; k++)
                    e1[k] = B[k] - A[k], e2[k] = C[k] - A[k];
                n[0] = e1[1] * e2[2] - e1[2] * e2[1];
                n[1] = e1[2] * e2[0] - e1[0] * e2[2];
                n[2] = e1[0] * e2[1] - e1[1] * e2[0];
                double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
                if (len < eps)
                    continue;
                for (int k = 0; k < 3; k++)
                    n[k] /= len;
                int on[POLY_MAX_VERTS], non = 0, above = 0, below = 0;
                for (int v = 0; v < ph->n; v++) {
                    double d = (ph->v[v][0] - A[0]) * n[0] + (ph->v[v][1] - A[1]) * n[1] +
                               (ph->v[v][2] - A[2]) * n[2];
                    if (fabs(d) < 1e-7)
                        on[non++] = v;
                    else if (d > 0)
                        above++;
                    else
                        below++;
                }
                /* A face once: from its three lowest vertices. */
                if ((above && below) || non < 3 || on[0] != a || on[1] != b || on[2] != c)
                    continue;
                if (above)
                    for (int k = 0; k < 3; k++)
                        n[k] = -n[k];
                /* Order by angle about the centroid, counter-clockwise about n. */
                double cen[3] = {0, 0, 0}, u[3], w[3], ang[POLY_MAX_VERTS];
                for (int v = 0; v < non; v++)
                    for (int k = 0; k < 3; k++)
                        cen[k] += ph->v[on[v]][k] / non;
                for (int k = 0; k < 3; k++)
                    u[k] = ph->v[on[0]][k] - cen[k];
                w[0] = n[1] * u[2] - n[2] * u[1];
                w[1] = n[2] * u[0] - n[0] * u[2];
                w[2] = n[0] * u[1] - n[1] * u[0];
                for (int v = 0; v < non; v++) {
                    double d[3];
                    for (int k = 0; k < 3; k++)
                        d[k] = ph->v[on[v]][k] - cen[k];
                    ang[v] = atan2(d[0] * w[0] + d[1] * w[1] + d[2] * w[2],
                                   d[0] * u[0] + d[1] * u[1] + d[2] * u[2]);
                }
                for (int x = 1; x < non; x++) /* insertion sort by angle */
                    for (int y = x; y > 0 && ang[y] < ang[y - 1]; y--) {
                        double t = ang[y];
                        ang[y] = ang[y - 1];
                        ang[y - 1] = t;
                        int s = on[y];
                        on[y] = on[y - 1];
                        on[y - 1] = s;
                    }
                double pts[POLY_MAX_VERTS][3];
                for (int v = 0; v < non; v++)
                    for (int k = 0; k < 3; k++)
                        pts[v][k] = ph->v[on[v]][k] * scale;
                face(ip, (const double (*)[3])pts, non, n, wire);
            }
}

static void poly_face(interp *ip, const double (*pts)[3], int n, const double *normal, bool wire)
{
    set_normal(ip, normal);
    interp_prim_begin(ip, wire ? GL_LINE_LOOP : GL_POLYGON);
    for (int v = 0; v < n; v++)
        put_vertex(ip, pts[v]);
    interp_prim_end(ip);
}

void interp_glutpolyhedron(interp *ip, const rgl_cmd *cmd)
{
    if (!ip->scene)
        return;
    saved_current sc = save_current(ip);
    polyhedron ph;
    polyhedron_for(cmd->opcode, &ph);
    polyhedron_faces(&ph, 1, poly_face, ip, is_wire(cmd));
    restore_current(ip, &sc);
}

void interp_glutcube(interp *ip, const rgl_cmd *cmd)
{
    if (!ip->scene || !finite_args(ip, cmd, 0, 1))
        return;
    double size = arg_num(&cmd->arg[0]);
    saved_current sc = save_current(ip);
    if (is_wire(cmd) || !(exact_ok(ip, true, false, false) && size > 0 &&
                          emit_solid(ip, SCENE_SOLID_BOX, false, size / 2, size / 2, size / 2))) {
        polyhedron ph;
        polyhedron_for(RGL_OP_SolidCube, &ph);
        polyhedron_faces(&ph, size, poly_face, ip, is_wire(cmd));
    }
    restore_current(ip, &sc);
}

/* ---- Teapot ------------------------------------------------------------------------ */

typedef struct teapot_grid {
    int patch, n; /* n points per side */
    double size;
} teapot_grid;

/* freeglut's grid on a patch: point (i, j) at u = i/(n-1), v = j/(n-1),
 * texture coordinates (u, v). */
static void teapot_at(const void *ctx, int i, int j, surf_point *o)
{
    const teapot_grid *g = ctx;
    double u = (double)i / (g->n - 1), v = (double)j / (g->n - 1);
    teapot_eval(g->patch, u, v, o->p, o->n);
    for (int k = 0; k < 3; k++)
        o->p[k] *= g->size;
    o->t[0] = u;
    o->t[1] = v;
}

/* The solid teapot is the true curved surface (Newell's patches) where
 * exact_ok allows it; it is not closed (GL shows its inside where culling
 * removes the outside, the teapot being wound clockwise), so culling of
 * either face keeps freeglut's mesh. Otherwise freeglut's triangles, its
 * normals and texture coordinates; the wire teapot is its lines, 10 along
 * each direction of each patch. */
void interp_glutteapot(interp *ip, const rgl_cmd *cmd)
{
    if (!ip->scene || !finite_args(ip, cmd, 0, 1))
        return;
    double size = arg_num(&cmd->arg[0]);
    saved_current sc = save_current(ip);
    static const shape_style st = {GLU_SMOOTH, false, true, true, true};
    /* freeglut's fixed tessellation still counts toward the frame's bound:
     * a trace of many teapot calls is as cheap to write as one. */
    int cells = TEAPOT_SOLID_GRID - 1;
    if (!is_wire(cmd)) {
        if (!(size > 0 && exact_ok(ip, false, false, false) &&
              emit_solid(ip, SCENE_SOLID_TEAPOT, false, size, 0, 0)) &&
            tess_ok(ip, "glutSolidTeapot", TEAPOT_PATCHES * cells, 2 * cells))
            for (int p = 0; p < TEAPOT_PATCHES; p++) {
                teapot_grid g = {p, TEAPOT_SOLID_GRID, size};
                grid_fill(ip, &st, teapot_at, &g, g.n - 1, g.n - 1);
            }
    } else if (tess_ok(ip, "glutWireTeapot", TEAPOT_PATCHES * TEAPOT_WIRE_GRID,
                       2 * (TEAPOT_WIRE_GRID - 1))) {
        for (int p = 0; p < TEAPOT_PATCHES; p++) {
            teapot_grid g = {p, TEAPOT_WIRE_GRID, size};
            for (int k = 0; k < g.n; k++) {
                grid_line(ip, &st, teapot_at, &g, GL_LINE_STRIP, true, k, 0, g.n - 1);
                grid_line(ip, &st, teapot_at, &g, GL_LINE_STRIP, false, k, 0, g.n - 1);
            }
        }
    }
    restore_current(ip, &sc);
}
