/* interp_eval.c: evaluators (GL 1.x section 5.1): glMap1/glMap2, the map
 * grids, glEvalCoord, glEvalPoint and glEvalMesh.
 *
 * A map is a Bernstein polynomial of its control points over a normalised
 * domain, u' = (u - u1) / (u2 - u1). glEvalCoord evaluates the enabled maps
 * of its dimension and issues, as glColor, glNormal, glTexCoord and last
 * glVertex would, the values they give, except that the current colour,
 * normal and texture coordinates keep their values (the evaluated ones only
 * reach the vertex). The vertex goes into the open primitive through
 * interp_add_vertex, like glVertex, so lighting, colour material, textures,
 * culling and the vertex counts of the frame follow; glEvalMesh opens and
 * closes its own primitives through interp_prim_begin/interp_prim_end.
 *
 * The maps live in ip->st.eval (NULL while every map has its initial value),
 * context state that interp_copy_state carries and display lists see as
 * they are at glCallList. The grids are attributes (gl_attribs.eval, saved
 * by GL_EVAL_BIT), the enables caps (caps.def).
 */
#include "interp_internal.h"

#include <string.h>

#include "talloc.h"
#include "wire.h"

#define EVAL_TARGETS 9 /* COLOR_4, INDEX, NORMAL, TEXTURE_COORD_1..4, VERTEX_3, VERTEX_4 */
enum { E_COLOR, E_INDEX, E_NORMAL, E_TEX1, E_TEX2, E_TEX3, E_TEX4, E_VERTEX3, E_VERTEX4 };

typedef struct eval_map {
    int order[2];      /* u, v (1 for a glMap1) */
    double dom[2][2];  /* u1, u2; v1, v2 */
    double *pts;       /* order[0] x order[1] points of k values; NULL: the initial point */
} eval_map;

struct interp_eval {
    eval_map map[2][EVAL_TARGETS]; /* [0] glMap1, [1] glMap2 */
};

/* Values per point of target t (format/tables.c, shared with the recorder). */
static uint32_t comps(int t) { return rgl_map_components(GL_MAP1_COLOR_4 + (uint32_t)t, NULL); }

/* The initial map's single point (GL 1.x table 5.1): colour (1,1,1,1),
 * index 1, normal (0,0,1), texture (0,0,0,1), vertex (0,0,0,1). */
static const double initial[EVAL_TARGETS][4] = {
    {1, 1, 1, 1}, {1}, {0, 0, 1}, {0}, {0, 0}, {0, 0, 0}, {0, 0, 0, 1}, {0, 0, 0}, {0, 0, 0, 1},
};

static void eval_defaults(struct interp_eval *e)
{
    memset(e, 0, sizeof *e);
    for (int d = 0; d < 2; d++) {
        for (int t = 0; t < EVAL_TARGETS; t++) {
            e->map[d][t].order[0] = e->map[d][t].order[1] = 1;
            e->map[d][t].dom[0][1] = e->map[d][t].dom[1][1] = 1;
        }
    }
}

/* The evaluator state, created at its first change; NULL on allocation
 * failure (the scene is marked failed). */
static struct interp_eval *eval_get(interp *ip)
{
    if (!ip->st.eval) {
        ip->st.eval = tr_realloc(NULL, sizeof *ip->st.eval);
        if (!ip->st.eval) {
            if (ip->scene)
                ip->scene->failed = true;
            return NULL;
        }
        eval_defaults(ip->st.eval);
    }
    return ip->st.eval;
}

void interp_eval_free(interp *ip)
{
    if (!ip->st.eval)
        return;
    for (int d = 0; d < 2; d++)
        for (int t = 0; t < EVAL_TARGETS; t++)
            tr_free(ip->st.eval->map[d][t].pts);
    tr_free(ip->st.eval);
    ip->st.eval = NULL;
}

int interp_eval_copy(interp *dst, const interp *src)
{
    interp_eval_free(dst);
    if (!src->st.eval)
        return 0;
    struct interp_eval *e = tr_realloc(NULL, sizeof *e);
    if (!e)
        return -1;
    *e = *src->st.eval;
    int rc = 0;
    for (int d = 0; d < 2; d++) {
        for (int t = 0; t < EVAL_TARGETS; t++) {
            const eval_map *m = &src->st.eval->map[d][t];
            if (!m->pts)
                continue;
            size_t n = (size_t)m->order[0] * (size_t)m->order[1] * comps(t);
            e->map[d][t].pts = tr_realloc(NULL, n * sizeof(double));
            if (!e->map[d][t].pts) { /* that map falls back to its initial point */
                rc = -1;
                e->map[d][t] = (eval_map){{1, 1}, {{0, 1}, {0, 1}}, NULL};
                continue;
            }
            memcpy(e->map[d][t].pts, m->pts, n * sizeof(double));
        }
    }
    dst->st.eval = e;
    return rc;
}

/* ---- Bernstein polynomials ------------------------------------------------------- */

/* The Bezier curve of `order` points of k values (point i at p + i * step)
 * at t, by de Casteljau's construction: *val, and into der (may be NULL)
 * its derivative in t (0 for one point). */
static void bezier(const double *p, size_t step, int order, uint32_t k, double t, double *val,
                   double *der)
{
    double w[INTERP_MAX_EVAL_ORDER][4];
    for (int i = 0; i < order; i++)
        for (uint32_t c = 0; c < k; c++)
            w[i][c] = p[(size_t)i * step + c];
    for (int n = order - 1; n > 1; n--)
        for (int i = 0; i < n; i++)
            for (uint32_t c = 0; c < k; c++)
                w[i][c] = (1 - t) * w[i][c] + t * w[i + 1][c];
    for (uint32_t c = 0; c < k; c++) {
        if (order == 1) {
            val[c] = w[0][c];
            if (der)
                der[c] = 0;
        } else {
            val[c] = (1 - t) * w[0][c] + t * w[1][c];
            if (der)
                der[c] = (order - 1) * (w[1][c] - w[0][c]);
        }
    }
}

void interp_eval_curve(const double *pts, int order, uint32_t k, double t, double *out)
{
    bezier(pts, k, order, k, t, out, NULL);
}

void interp_eval_surface(const double *pts, int uorder, int vorder, uint32_t k, double u,
                         double v, double *out, double *du, double *dv)
{
    double q[INTERP_MAX_EVAL_ORDER][4], dq[INTERP_MAX_EVAL_ORDER][4];
    for (int i = 0; i < uorder; i++)
        bezier(pts + (size_t)i * (size_t)vorder * k, k, vorder, k, v, q[i], dq[i]);
    bezier(&q[0][0], 4, uorder, k, u, out, du);
    if (dv)
        bezier(&dq[0][0], 4, uorder, k, u, dv, NULL);
}

/* ---- Map definitions ----------------------------------------------------------- */

/* glMap1 and glMap2: the checks GL makes (INVALID_ENUM for the target,
 * INVALID_VALUE for an empty domain, a stride below k or an order outside
 * 1..GL_MAX_EVAL_ORDER), then the packed points of the record. */
static void define_map(interp *ip, const rgl_cmd *cmd, bool two)
{
    if (interp_reject_in_begin(ip))
        return;
    uint32_t target = arg_enum(cmd, 0);
    bool is2;
    uint32_t k = rgl_map_components(target, &is2);
    if (k == 0 || is2 != two) {
        interp_bad_enum(ip, "map target", target);
        return;
    }
    int dims = two ? 2 : 1;
    double dom[2][2] = {{0, 1}, {0, 1}};
    int order[2] = {1, 1};
    for (int d = 0; d < dims; d++) {
        const rgl_arg *a = &cmd->arg[1 + 4 * d];
        dom[d][0] = arg_num(&a[0]);
        dom[d][1] = arg_num(&a[1]);
        int64_t stride = rgl_arg_i(&a[2], 0), ord = rgl_arg_i(&a[3], 0);
        if (!isfinite(dom[d][0]) || !isfinite(dom[d][1])) {
            interp_diag(ip, DIAG_BAD_NUMBER, "map domain not finite");
            return;
        }
        if (dom[d][0] == dom[d][1] || stride < (int64_t)k || ord < 1 ||
            ord > INTERP_MAX_EVAL_ORDER) {
            interp_bad_value(ip, "map domain empty, stride below the point size or order "
                                 "outside 1..GL_MAX_EVAL_ORDER");
            return;
        }
        order[d] = (int)ord;
    }
    const rgl_arg *blob = &cmd->arg[cmd->nargs - 1];
    size_t size = cmd->arg[1].type == RGL_T_d ? 8 : 4;
    size_t n = (size_t)order[0] * (size_t)order[1] * k;
    if (blob->kind != RGL_ARG_BLOB || blob->count != n * size) {
        interp_bad_value(ip, "map points do not match the order and target");
        return;
    }
    double *pts = tr_realloc(NULL, n * sizeof *pts);
    if (!pts) {
        if (ip->scene)
            ip->scene->failed = true;
        return;
    }
    for (size_t i = 0; i < n; i++) {
        const uint8_t *b = blob->bytes + i * size;
        pts[i] = size == 8 ? rgl_bits_f64(rgl_get_u64(b)) : rgl_bits_f32(rgl_get_u32(b));
        if (!isfinite(pts[i])) {
            interp_diag(ip, DIAG_BAD_NUMBER, "map control point not finite");
            tr_free(pts);
            return;
        }
    }
    struct interp_eval *e = eval_get(ip);
    if (!e) {
        tr_free(pts);
        return;
    }
    eval_map *m = &e->map[two][target - (two ? GL_MAP2_COLOR_4 : GL_MAP1_COLOR_4)];
    tr_free(m->pts);
    m->pts = pts;
    memcpy(m->order, order, sizeof order);
    memcpy(m->dom, dom, sizeof dom);
}

void interp_map1(interp *ip, const rgl_cmd *cmd) { define_map(ip, cmd, false); }

void interp_map2(interp *ip, const rgl_cmd *cmd) { define_map(ip, cmd, true); }

static void define_grid(interp *ip, const rgl_cmd *cmd, int dims)
{
    if (interp_reject_in_begin(ip))
        return;
    int64_t n[2] = {1, 1};
    double g[2][2] = {{0, 1}, {0, 1}};
    for (int d = 0; d < dims; d++) {
        n[d] = rgl_arg_i(&cmd->arg[3 * d], 0);
        g[d][0] = arg_num(&cmd->arg[3 * d + 1]);
        g[d][1] = arg_num(&cmd->arg[3 * d + 2]);
        if (n[d] <= 0 || n[d] > INT32_MAX) {
            interp_bad_value(ip, "grid partitions not positive");
            return;
        }
        if (!isfinite(g[d][0]) || !isfinite(g[d][1])) {
            interp_diag(ip, DIAG_BAD_NUMBER, "grid domain not finite");
            return;
        }
    }
    gl_attribs *a = &ip->st.a;
    for (int d = 0; d < dims; d++) {
        a->eval.grid_n[dims - 1][d] = (int32_t)n[d];
        a->eval.grid[dims - 1][d][0] = g[d][0];
        a->eval.grid[dims - 1][d][1] = g[d][1];
    }
}

void interp_mapgrid1(interp *ip, const rgl_cmd *cmd) { define_grid(ip, cmd, 1); }

void interp_mapgrid2(interp *ip, const rgl_cmd *cmd) { define_grid(ip, cmd, 2); }

/* ---- Evaluation ------------------------------------------------------------------ */

static bool map_on(const interp *ip, int two, int t)
{
    int cap = two ? INTERP_CAP_MAP2_COLOR_4 : INTERP_CAP_MAP1_COLOR_4;
    return ip->st.a.caps[cap + t] != 0;
}

/* Map t of dimension `two` at (u, v): value, and the derivatives in the
 * normalised u' and v' when du is given (glMap2 only). */
static void eval_map_at(const interp *ip, int two, int t, double u, double v, double *out,
                        double *du, double *dv)
{
    const eval_map *m = ip->st.eval ? &ip->st.eval->map[two][t] : NULL;
    if (!m || !m->pts) {
        memcpy(out, initial[t], comps(t) * sizeof *out);
        if (du)
            for (uint32_t c = 0; c < comps(t); c++)
                du[c] = dv[c] = 0;
        return;
    }
    double uu = (u - m->dom[0][0]) / (m->dom[0][1] - m->dom[0][0]);
    if (!two) {
        interp_eval_curve(m->pts, m->order[0], comps(t), uu, out);
        return;
    }
    double vv = (v - m->dom[1][0]) / (m->dom[1][1] - m->dom[1][0]);
    interp_eval_surface(m->pts, m->order[0], m->order[1], comps(t), uu, vv, out, du, dv);
}

/* glEvalCoord1/2 at (u, v) (two: glEvalCoord2). */
static void eval_coord(interp *ip, int two, double u, double v)
{
    int vt = map_on(ip, two, E_VERTEX4) ? E_VERTEX4 : map_on(ip, two, E_VERTEX3) ? E_VERTEX3 : -1;
    if (vt < 0)
        return; /* no vertex map: nothing is drawn and the current values stay */
    if (!ip->in_begin) {
        interp_diag(ip, DIAG_IGNORED, "evaluated vertex outside glBegin/glEnd ignored");
        return;
    }
    if (ip->prim_skip)
        return;
    if (!isfinite(u) || !isfinite(v)) {
        interp_diag(ip, DIAG_BAD_NUMBER, "evaluator coordinate not finite");
        return;
    }
    gl_attribs *a = &ip->st.a;
    float color[4], normal[3], texcoord[4];
    gl_material material[2];
    memcpy(color, a->current.color, sizeof color);
    memcpy(normal, a->current.normal, sizeof normal);
    memcpy(texcoord, a->current.texcoord, sizeof texcoord);
    memcpy(material, a->lighting.material, sizeof material);

    double val[4], du[4], dv[4];
    if (map_on(ip, two, E_INDEX)) /* GL 2.1 5.1: the index goes unused in RGBA */
        interp_note_held(ip, DIAG_NOTE_EVAL_INDEX, "an RGBA window ignores colour indices");
    if (map_on(ip, two, E_COLOR)) {
        eval_map_at(ip, two, E_COLOR, u, v, val, NULL, NULL);
        for (int c = 0; c < 4; c++)
            a->current.color[c] = (float)val[c];
        if (a->caps[INTERP_CAP_COLOR_MATERIAL])
            interp_cm_colour(ip);
    }
    if (map_on(ip, two, E_NORMAL)) {
        eval_map_at(ip, two, E_NORMAL, u, v, val, NULL, NULL);
        for (int c = 0; c < 3; c++)
            a->current.normal[c] = (float)val[c];
    }
    for (int t = E_TEX4; t >= E_TEX1; t--) { /* the highest-dimensional map wins */
        if (!map_on(ip, two, t))
            continue;
        static const float def[4] = {0, 0, 0, 1};
        eval_map_at(ip, two, t, u, v, val, NULL, NULL);
        for (uint32_t c = 0; c < 4; c++)
            a->current.texcoord[c] = c < comps(t) ? (float)val[c] : def[c];
        break;
    }
    bool autonormal = two && a->caps[INTERP_CAP_AUTO_NORMAL];
    eval_map_at(ip, two, vt, u, v, val, autonormal ? du : NULL, autonormal ? dv : NULL);
    double w = vt == E_VERTEX4 ? val[3] : 1;
    if (autonormal) {
        /* GL 1.x 5.1: the normal is dp/du x dp/dv, normalised; for a
         * homogeneous map, of the derivatives of (x/w, y/w, z/w), here
         * scaled by w^2 (the direction is the same). */
        if (vt == E_VERTEX4) {
            for (int c = 0; c < 3; c++) {
                du[c] = du[c] * w - du[3] * val[c];
                dv[c] = dv[c] * w - dv[3] * val[c];
            }
        }
        double n[3] = {du[1] * dv[2] - du[2] * dv[1], du[2] * dv[0] - du[0] * dv[2],
                       du[0] * dv[1] - du[1] * dv[0]};
        double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        for (int c = 0; c < 3; c++)
            a->current.normal[c] = (float)(len > 0 ? n[c] / len : n[c]);
    }
    interp_add_vertex(ip, val[0], val[1], val[2], w);

    memcpy(a->current.color, color, sizeof color);
    memcpy(a->current.normal, normal, sizeof normal);
    memcpy(a->current.texcoord, texcoord, sizeof texcoord);
    memcpy(a->lighting.material, material, sizeof material);
}

void interp_evalcoord1(interp *ip, const rgl_cmd *cmd) { eval_coord(ip, 0, cmd_value(cmd, 0), 0); }

void interp_evalcoord2(interp *ip, const rgl_cmd *cmd)
{
    eval_coord(ip, 1, cmd_value(cmd, 0), cmd_value(cmd, 1));
}

/* Grid point i of dimension dims' axis d: i * (end - start) / n + start
 * (GL 1.x 5.1, with the point at i == n exactly the end). */
static double grid_at(const interp *ip, int dims, int d, int64_t i)
{
    int32_t n = ip->st.a.eval.grid_n[dims - 1][d];
    double g0 = ip->st.a.eval.grid[dims - 1][d][0], g1 = ip->st.a.eval.grid[dims - 1][d][1];
    if (i == n)
        return g1;
    return (double)i * (g1 - g0) / n + g0;
}

void interp_evalpoint1(interp *ip, const rgl_cmd *cmd)
{
    eval_coord(ip, 0, grid_at(ip, 1, 0, rgl_arg_i(&cmd->arg[0], 0)), 0);
}

void interp_evalpoint2(interp *ip, const rgl_cmd *cmd)
{
    eval_coord(ip, 1, grid_at(ip, 2, 0, rgl_arg_i(&cmd->arg[0], 0)),
               grid_at(ip, 2, 1, rgl_arg_i(&cmd->arg[1], 0)));
}

/* A trace may ask for a grid of 2^31 partitions; GL would draw them all,
 * but a few bytes must not cost minutes or gigabytes here. Above these many
 * grid points for one mesh, or with the frame's tessellated shapes
 * (interp_shape.c) over their budget, the mesh is skipped with a
 * diagnostic. A 512 x 512 mesh is within the first. */
#define EVAL_MESH_MAX_POINTS (1u << 18)
#define EVAL_FRAME_MAX_POINTS (1u << 21)

static bool mesh_range(interp *ip, int64_t lo, int64_t hi, int64_t lo2, int64_t hi2)
{
    uint64_t a = hi >= lo ? (uint64_t)(hi - lo + 1) : 0;
    uint64_t b = hi2 >= lo2 ? (uint64_t)(hi2 - lo2 + 1) : 0;
    if (a > EVAL_MESH_MAX_POINTS || b > EVAL_MESH_MAX_POINTS || a * b > EVAL_MESH_MAX_POINTS) {
        interp_diag(ip, DIAG_LIMIT, "evaluator mesh of %llu x %llu points skipped: over %u",
                    (unsigned long long)a, (unsigned long long)b, EVAL_MESH_MAX_POINTS);
        return false;
    }
    if (ip->shape_facets + a * b > EVAL_FRAME_MAX_POINTS) {
        interp_diag(ip, DIAG_LIMIT, "evaluator mesh skipped: the frame's meshes and shapes "
                                    "exceed %u points", EVAL_FRAME_MAX_POINTS);
        return false;
    }
    ip->shape_facets += a * b;
    return a > 0 && b > 0;
}

/* glEvalMesh1(mode, i1, i2): Begin(POINTS or LINE_STRIP), EvalCoord1 at
 * grid points i1..i2, End (GL 1.x 5.1). */
void interp_evalmesh1(interp *ip, const rgl_cmd *cmd)
{
    GLenum mode = arg_enum(cmd, 0);
    int64_t i1 = rgl_arg_i(&cmd->arg[1], 0), i2 = rgl_arg_i(&cmd->arg[2], 0);
    if (mode != GL_POINT && mode != GL_LINE) {
        interp_bad_enum(ip, "mesh mode", mode);
        return;
    }
    if (!map_on(ip, 0, E_VERTEX3) && !map_on(ip, 0, E_VERTEX4))
        return;
    if (!mesh_range(ip, i1, i2, 0, 0))
        return;
    if (interp_prim_begin(ip, mode == GL_POINT ? GL_POINTS : GL_LINE_STRIP))
        for (int64_t i = i1; i <= i2; i++)
            eval_coord(ip, 0, grid_at(ip, 1, 0, i), 0);
    interp_prim_end(ip);
}

/* glEvalMesh2(mode, i1, i2, j1, j2), GL 1.x 5.1: GL_FILL is one quad strip
 * per row j of the grid, (i, j) then (i, j + 1) for i = i1..i2; GL_LINE a
 * line strip along each row j = j1..j2, then along each column i = i1..i2;
 * GL_POINT the points (i, j), rows in order. */
void interp_evalmesh2(interp *ip, const rgl_cmd *cmd)
{
    GLenum mode = arg_enum(cmd, 0);
    int64_t i1 = rgl_arg_i(&cmd->arg[1], 0), i2 = rgl_arg_i(&cmd->arg[2], 0);
    int64_t j1 = rgl_arg_i(&cmd->arg[3], 0), j2 = rgl_arg_i(&cmd->arg[4], 0);
    if (mode != GL_POINT && mode != GL_LINE && mode != GL_FILL) {
        interp_bad_enum(ip, "mesh mode", mode);
        return;
    }
    if (!map_on(ip, 1, E_VERTEX3) && !map_on(ip, 1, E_VERTEX4))
        return;
    if (!mesh_range(ip, i1, i2, j1, j2))
        return;
    switch (mode) {
    case GL_FILL:
        for (int64_t j = j1; j < j2; j++) {
            double v0 = grid_at(ip, 2, 1, j), v1 = grid_at(ip, 2, 1, j + 1);
            if (interp_prim_begin(ip, GL_QUAD_STRIP)) {
                for (int64_t i = i1; i <= i2; i++) {
                    double u = grid_at(ip, 2, 0, i);
                    eval_coord(ip, 1, u, v0);
                    eval_coord(ip, 1, u, v1);
                }
            }
            interp_prim_end(ip);
        }
        break;
    case GL_LINE:
        for (int64_t j = j1; j <= j2; j++) {
            double v = grid_at(ip, 2, 1, j);
            if (interp_prim_begin(ip, GL_LINE_STRIP))
                for (int64_t i = i1; i <= i2; i++)
                    eval_coord(ip, 1, grid_at(ip, 2, 0, i), v);
            interp_prim_end(ip);
        }
        for (int64_t i = i1; i <= i2; i++) {
            double u = grid_at(ip, 2, 0, i);
            if (interp_prim_begin(ip, GL_LINE_STRIP))
                for (int64_t j = j1; j <= j2; j++)
                    eval_coord(ip, 1, u, grid_at(ip, 2, 1, j));
            interp_prim_end(ip);
        }
        break;
    default:
        if (interp_prim_begin(ip, GL_POINTS))
            for (int64_t j = j1; j <= j2; j++)
                for (int64_t i = i1; i <= i2; i++)
                    eval_coord(ip, 1, grid_at(ip, 2, 0, i), grid_at(ip, 2, 1, j));
        interp_prim_end(ip);
        break;
    }
}
