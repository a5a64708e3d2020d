/* interp_nurbs.c: GLU NURBS (GLU 1.3 chapter 7): the NURBS objects'
 * properties, gluBeginSurface .. gluEndSurface, gluBeginCurve ..
 * gluEndCurve, trim loops (gluBeginTrim, gluPwlCurve, gluNurbsCurve of
 * GLU_MAP1_TRIM_2/3) and the drawing GLU does at the end calls.
 *
 * GLU draws a NURBS through GL's evaluators: a vertex gets the value of
 * the surface's GL_MAP2_VERTEX_3/4 piece, the colour, normal and texture
 * coordinates of the other pieces given, and, with no normal piece, the
 * normal GL_AUTO_NORMAL gives (du x dv) when the program enabled it, else
 * the current normal. Here the pieces are evaluated directly (Cox-de Boor
 * basis functions, homogeneous for the rational types) at the nodes of a
 * grid over the parameter domain: every knot span cut in GLU_DOMAIN_DISTANCE's
 * steps (GLU's own grid), or for the methods that measure on screen
 * (GLU_PATH_LENGTH, the default) in NURBS_SPAN_STEPS or a bound on GLU's
 * steps from the span's control polygon in window space, whichever are
 * more: at least as fine as GLU's; the ray tracer smooths with normals.
 * The vertices go through interp_add_vertex like glEvalCoord's, so
 * lighting, colour material, textures and culling follow.
 *
 * Trims: the loops are polygons in the (u, v) domain; a grid cell is drawn
 * when its centre lies inside (winding number above 0: outer loops
 * counter-clockwise, holes clockwise, as GLU asks; as GLU, a surface with
 * trims but no outer loop draws nothing). The grid also gets a
 * line at every trim edge parallel to an axis, so axis-aligned trims cut
 * exactly; other trim edges cut along the grid (a note says so).
 *
 * The state lives in ip->st.nurbs (NULL until the first NURBS call): the
 * objects' properties are context state (interp_copy_state carries them);
 * the pieces of an open surface or curve are not.
 */
#include "interp_internal.h"
#include "numfmt.h"

#include <GL/glu.h>
#include <stdlib.h>
#include <string.h>

#include "talloc.h"
#include "wire.h"

#define NURBS_OBJECTS 16
#define NURBS_MAX_ORDER 24    /* GLU's MAXORDER */
#define NURBS_SPAN_STEPS 16   /* grid steps per knot span, at least */
#define NURBS_MAX_STEPS 1024  /* grid lines along one axis, at most */
#define NURBS_CURVE_STEPS 32  /* steps per knot span of a curve or trim curve */
#define NURBS_MAX_PIECES 16   /* pieces of one surface or curve kept */
#define NURBS_MAX_TRIM (1u << 16) /* trim points of one surface */
#define NURBS_MAX_GRID (1u << 18) /* grid points of one surface */
/* Grid points of the frame's NURBS and evaluator meshes (interp_eval.c
 * counts its meshes in shape_facets too). */
#define NURBS_FRAME_MAX_POINTS (1u << 21)

typedef struct nurbs_props {
    uint32_t id; /* 0: free slot */
    GLenum display, method, mode;
    double tolerance, ustep, vstep;
    bool own_matrices; /* GLU_AUTO_LOAD_MATRIX false: sample with these */
    bool have_matrices; /* gluLoadSamplingMatrices was called */
    mat4 model, proj;
    int32_t view[4];
} nurbs_props;

/* One gluNurbsSurface or gluNurbsCurve: n[d] points along axis d (n[1] =
 * 1 for a curve), k values each, homogeneous as GL's maps. */
typedef struct nurbs_piece {
    GLenum type;
    uint32_t k;
    int order[2], n[2];
    double *knots[2];
    double *pts;
} nurbs_piece;

enum { N_NONE, N_SURFACE, N_CURVE };

struct interp_nurbs {
    nurbs_props obj[NURBS_OBJECTS];
    /* The open surface or curve. */
    int open;
    uint32_t open_id;
    bool in_trim;
    nurbs_piece piece[NURBS_MAX_PIECES];
    int npieces;
    /* Trim loops: points (u, v); loop i ends before loop_end[i]. */
    double (*tp)[2];
    size_t ntp, cap_tp;
    size_t *loop_end;
    size_t nloops, cap_loops;
};

static const nurbs_props props_default = {
    .display = GLU_FILL,
    .method = GLU_PATH_LENGTH,
    .mode = GLU_NURBS_RENDERER,
    .tolerance = 50.0,
    .ustep = 100.0,
    .vstep = 100.0,
};

/* ---- Basis functions -------------------------------------------------------------- */

/* The knot span of u for n points of `order` over knots kn: the s in
 * order-1 .. n-1 with kn[s] <= u < kn[s+1], u clamped to the domain
 * [kn[order-1], kn[n]] (its end falls in the last non-empty span). -1 when
 * every span is empty. */
static int find_span(const double *kn, int n, int order, double u)
{
    int lo = order - 1, hi = n - 1;
    if (u >= kn[n]) {
        for (int s = hi; s >= lo; s--)
            if (kn[s] < kn[s + 1])
                return s;
        return -1;
    }
    if (u < kn[lo]) {
        for (int s = lo; s <= hi; s++)
            if (kn[s] < kn[s + 1])
                return s;
        return -1;
    }
    /* The last s with kn[s] <= u; kn[s + 1] > u then (a hostile trace
     * may give thousands of knots: a binary search). */
    while (lo < hi) {
        int mid = lo + (hi - lo + 1) / 2;
        if (kn[mid] <= u)
            lo = mid;
        else
            hi = mid - 1;
    }
    return lo;
}

/* The order non-zero basis functions at u, N[j] of point s - order + 1 + j,
 * and their derivatives dN (may be NULL); returns s, or -1. A 0/0 term of
 * the recurrence counts as 0 (repeated knots). */
static int basis(const double *kn, int n, int order, double u, double *N, double *dN)
{
    int s = find_span(kn, n, order, u);
    if (s < 0)
        return -1;
    if (u < kn[order - 1])
        u = kn[order - 1];
    if (u > kn[n])
        u = kn[n];
    double B[NURBS_MAX_ORDER][NURBS_MAX_ORDER];
    int p = order - 1;
    B[0][0] = 1;
    for (int d = 1; d <= p; d++) {
        for (int j = 0; j <= d; j++) {
            int i = s - d + j;
            double a = j >= 1 ? B[d - 1][j - 1] : 0, b = j <= d - 1 ? B[d - 1][j] : 0;
            double l = kn[i + d] - kn[i], r = kn[i + d + 1] - kn[i + 1];
            B[d][j] = (l > 0 ? (u - kn[i]) / l * a : 0) + (r > 0 ? (kn[i + d + 1] - u) / r * b : 0);
        }
    }
    for (int j = 0; j <= p; j++) {
        N[j] = B[p][j];
        if (!dN)
            continue;
        if (p == 0) {
            dN[j] = 0;
            continue;
        }
        int i = s - p + j;
        double a = j >= 1 ? B[p - 1][j - 1] : 0, b = j <= p - 1 ? B[p - 1][j] : 0;
        double l = kn[i + p] - kn[i], r = kn[i + p + 1] - kn[i + 1];
        dN[j] = (l > 0 ? p / l * a : 0) - (r > 0 ? p / r * b : 0);
    }
    return s;
}

bool interp_nurbs_curve_at(const double *pts, uint32_t k, const double *knots, int n, int order,
                           double u, double *out, double *der)
{
    double N[NURBS_MAX_ORDER], dN[NURBS_MAX_ORDER];
    if (order < 1 || order > NURBS_MAX_ORDER || n < order)
        return false;
    int s = basis(knots, n, order, u, N, dN);
    if (s < 0)
        return false;
    for (uint32_t c = 0; c < k; c++) {
        out[c] = 0;
        if (der)
            der[c] = 0;
    }
    for (int j = 0; j < order; j++) {
        const double *p = pts + (size_t)(s - order + 1 + j) * k;
        for (uint32_t c = 0; c < k; c++) {
            out[c] += N[j] * p[c];
            if (der)
                der[c] += dN[j] * p[c];
        }
    }
    return true;
}

bool interp_nurbs_surface_at(const double *pts, uint32_t k, const double *uknots, int un,
                             int uorder, const double *vknots, int vn, int vorder, double u,
                             double v, double *out, double *du, double *dv)
{
    double Nu[NURBS_MAX_ORDER], dNu[NURBS_MAX_ORDER], Nv[NURBS_MAX_ORDER], dNv[NURBS_MAX_ORDER];
    if (uorder < 1 || uorder > NURBS_MAX_ORDER || un < uorder || vorder < 1 ||
        vorder > NURBS_MAX_ORDER || vn < vorder || k > 4)
        return false;
    int su = basis(uknots, un, uorder, u, Nu, dNu), sv = basis(vknots, vn, vorder, v, Nv, dNv);
    if (su < 0 || sv < 0)
        return false;
    for (uint32_t c = 0; c < k; c++) {
        out[c] = 0;
        if (du)
            du[c] = dv[c] = 0;
    }
    for (int a = 0; a < uorder; a++) {
        for (int b = 0; b < vorder; b++) {
            const double *p = pts + ((size_t)(su - uorder + 1 + a) * (size_t)vn +
                                     (size_t)(sv - vorder + 1 + b)) * k;
            for (uint32_t c = 0; c < k; c++) {
                out[c] += Nu[a] * Nv[b] * p[c];
                if (du) {
                    du[c] += dNu[a] * Nv[b] * p[c];
                    dv[c] += Nu[a] * dNv[b] * p[c];
                }
            }
        }
    }
    return true;
}

/* ---- State ------------------------------------------------------------------------- */

static struct interp_nurbs *nurbs_get(interp *ip)
{
    if (!ip->st.nurbs) {
        ip->st.nurbs = tr_realloc(NULL, sizeof *ip->st.nurbs);
        if (!ip->st.nurbs) {
            if (ip->scene)
                ip->scene->failed = true;
            return NULL;
        }
        memset(ip->st.nurbs, 0, sizeof *ip->st.nurbs);
    }
    return ip->st.nurbs;
}

static void pieces_clear(struct interp_nurbs *nb)
{
    for (int i = 0; i < nb->npieces; i++) {
        tr_free(nb->piece[i].knots[0]);
        tr_free(nb->piece[i].knots[1]);
        tr_free(nb->piece[i].pts);
    }
    nb->npieces = 0;
    nb->ntp = nb->nloops = 0;
    nb->open = N_NONE;
    nb->in_trim = false;
}

void interp_nurbs_free(interp *ip)
{
    if (!ip->st.nurbs)
        return;
    pieces_clear(ip->st.nurbs);
    tr_free(ip->st.nurbs->tp);
    tr_free(ip->st.nurbs->loop_end);
    tr_free(ip->st.nurbs);
    ip->st.nurbs = NULL;
}

int interp_nurbs_copy(interp *dst, const interp *src)
{
    interp_nurbs_free(dst);
    if (!src->st.nurbs)
        return 0;
    struct interp_nurbs *nb = tr_realloc(NULL, sizeof *nb);
    if (!nb)
        return -1;
    memset(nb, 0, sizeof *nb);
    memcpy(nb->obj, src->st.nurbs->obj, sizeof nb->obj);
    dst->st.nurbs = nb;
    return 0;
}

static uint32_t nurbs_handle(const rgl_cmd *cmd) { return (uint32_t)cmd->arg[0].v.u; }

/* The slot of object id (made when `make`; a full table reuses one by id). */
static nurbs_props *props_slot(interp *ip, uint32_t id, bool make)
{
    if (id == 0)
        return NULL;
    struct interp_nurbs *nb = make ? nurbs_get(ip) : ip->st.nurbs;
    if (!nb)
        return NULL;
    nurbs_props *free_slot = NULL;
    for (int i = 0; i < NURBS_OBJECTS; i++) {
        if (nb->obj[i].id == id)
            return &nb->obj[i];
        if (!free_slot && nb->obj[i].id == 0)
            free_slot = &nb->obj[i];
    }
    if (!make)
        return NULL;
    if (!free_slot)
        free_slot = &nb->obj[id % NURBS_OBJECTS];
    *free_slot = props_default;
    free_slot->id = id;
    return free_slot;
}

static nurbs_props props_of(interp *ip, uint32_t id)
{
    const nurbs_props *p = props_slot(ip, id, false);
    return p ? *p : props_default;
}

void interp_newnurbs(interp *ip, const rgl_cmd *cmd)
{
    nurbs_props *p = props_slot(ip, nurbs_handle(cmd), true);
    if (p) {
        uint32_t id = p->id;
        *p = props_default;
        p->id = id;
    }
}

void interp_deletenurbs(interp *ip, const rgl_cmd *cmd)
{
    nurbs_props *p = props_slot(ip, nurbs_handle(cmd), false);
    if (p)
        memset(p, 0, sizeof *p);
}

/* GLU reports a bad property value through the object's error callback,
 * not as a GL error: the call is ignored with a diagnostic. */
void interp_nurbsproperty(interp *ip, const rgl_cmd *cmd)
{
    GLenum prop = arg_enum(cmd, 1);
    double v = arg_num(&cmd->arg[2]);
    if (!isfinite(v)) {
        interp_diag(ip, DIAG_BAD_NUMBER, "NURBS property value not finite");
        return;
    }
    nurbs_props *p = props_slot(ip, nurbs_handle(cmd), true);
    if (!p)
        return;
    GLenum e = interp_enum_of(v);
    switch (prop) {
    case GLU_DISPLAY_MODE:
        if (e != GLU_FILL && e != GLU_OUTLINE_POLYGON && e != GLU_OUTLINE_PATCH)
            goto bad;
        p->display = e;
        break;
    case GLU_SAMPLING_METHOD:
        if (e != GLU_PATH_LENGTH && e != GLU_PARAMETRIC_ERROR && e != GLU_DOMAIN_DISTANCE &&
            e != GLU_OBJECT_PATH_LENGTH && e != GLU_OBJECT_PARAMETRIC_ERROR)
            goto bad;
        p->method = e;
        break;
    case GLU_NURBS_MODE:
        if (e != GLU_NURBS_RENDERER && e != GLU_NURBS_TESSELLATOR)
            goto bad;
        p->mode = e;
        break;
    case GLU_SAMPLING_TOLERANCE:
    case GLU_PARAMETRIC_TOLERANCE:
        if (v <= 0)
            goto bad;
        p->tolerance = v;
        break;
    case GLU_U_STEP:
    case GLU_V_STEP:
        if (v <= 0)
            goto bad;
        *(prop == GLU_U_STEP ? &p->ustep : &p->vstep) = v;
        break;
    case GLU_AUTO_LOAD_MATRIX:
        p->own_matrices = v == 0;
        break;
    case GLU_CULLING:
        break; /* skips what is off screen: not the picture */
    default:
        interp_diag(ip, DIAG_IGNORED, "gluNurbsProperty: unknown property %u ignored", prop);
        return;
    }
    return;
bad: {
    char num[NUMFMT_F32_ROOM + 1];
    num[numfmt_f32(num, v)] = '\0';
    interp_diag(ip, DIAG_IGNORED, "gluNurbsProperty: bad value %s for property %u ignored", num,
                prop);
}
}

/* The matrices and viewport GLU_PATH_LENGTH measures with while
 * GLU_AUTO_LOAD_MATRIX is false (GLU 1.3 7.6): they steer the grid's
 * density only. */
void interp_loadsampling(interp *ip, const rgl_cmd *cmd)
{
    nurbs_props *p = props_slot(ip, nurbs_handle(cmd), true);
    if (!p)
        return;
    mat4 model, proj;
    for (uint32_t i = 0; i < 16; i++) {
        model.m[i] = rgl_arg_f(&cmd->arg[1], i);
        proj.m[i] = rgl_arg_f(&cmd->arg[2], i);
        if (!isfinite(model.m[i]) || !isfinite(proj.m[i])) {
            interp_diag(ip, DIAG_BAD_NUMBER, "sampling matrix not finite");
            return;
        }
    }
    p->model = model;
    p->proj = proj;
    for (int i = 0; i < 4; i++) {
        int64_t x = rgl_arg_i(&cmd->arg[3 + i], 0);
        p->view[i] = x < -(1 << 24) ? -(1 << 24) : x > (1 << 24) ? (1 << 24) : (int32_t)x;
    }
    p->have_matrices = true;
}

void interp_nurbsbegin(interp *ip, const rgl_cmd *cmd)
{
    struct interp_nurbs *nb = nurbs_get(ip);
    if (!nb)
        return;
    uint32_t op = cmd->opcode;
    if (op == RGL_OP_BeginTrim) {
        if (nb->open != N_SURFACE || nb->in_trim) {
            interp_diag(ip, DIAG_IGNORED, "gluBeginTrim outside a surface or inside a trim");
            return;
        }
        nb->in_trim = true;
        return;
    }
    if (nb->open != N_NONE) {
        /* GLU reports a nesting error; the open one is dropped. */
        interp_diag(ip, DIAG_IGNORED, "GLU NURBS surface or curve begun inside another: the "
                                      "first dropped");
        pieces_clear(nb);
    }
    nb->open = op == RGL_OP_BeginSurface ? N_SURFACE : N_CURVE;
    nb->open_id = nurbs_handle(cmd);
}

/* ---- Pieces ---------------------------------------------------------------------- */

/* count little-endian singles from blob a into a new array; NULL after a
 * diagnostic when the blob does not hold exactly that many finite values. */
static double *blob_floats(interp *ip, const rgl_arg *a, size_t count, const char *what)
{
    if (a->kind != RGL_ARG_BLOB || count == 0 || a->count != count * 4) {
        interp_diag(ip, DIAG_IGNORED, "GLU NURBS %s: the data do not match the sizes", what);
        return NULL;
    }
    double *v = tr_realloc(NULL, count * sizeof *v);
    if (!v) {
        if (ip->scene)
            ip->scene->failed = true;
        return NULL;
    }
    for (size_t i = 0; i < count; i++) {
        v[i] = rgl_bits_f32(rgl_get_u32(a->bytes + 4 * i));
        if (!isfinite(v[i])) {
            interp_diag(ip, DIAG_BAD_NUMBER, "GLU NURBS %s not finite", what);
            tr_free(v);
            return NULL;
        }
    }
    return v;
}

/* Knots must not decrease (GLU: GLU_NURBS_ERROR4). */
static bool knots_ok(const double *kn, int count)
{
    for (int i = 1; i < count; i++)
        if (kn[i] < kn[i - 1])
            return false;
    return true;
}

/* Values per point of a piece's type (0: not one GLU takes there). */
static uint32_t piece_k(GLenum type, bool surface)
{
    if (!surface && (type == GLU_MAP1_TRIM_2 || type == GLU_MAP1_TRIM_3))
        return type == GLU_MAP1_TRIM_2 ? 2 : 3;
    bool two;
    uint32_t k = rgl_map_components(type, &two);
    return two == surface ? k : 0;
}

static bool grow(void **p, size_t *cap, size_t need, size_t size)
{
    if (need <= *cap)
        return true;
    size_t c = *cap ? *cap : 64;
    while (c < need)
        c *= 2;
    void *q = tr_realloc(*p, c * size);
    if (!q)
        return false;
    *p = q;
    *cap = c;
    return true;
}

/* Appends (u, v) to the open trim loop. */
static bool trim_add(interp *ip, struct interp_nurbs *nb, double u, double v)
{
    if (nb->ntp >= NURBS_MAX_TRIM) {
        interp_diag(ip, DIAG_LIMIT, "GLU NURBS trim of over %u points: the rest dropped",
                    NURBS_MAX_TRIM);
        return false;
    }
    size_t start = nb->nloops ? nb->loop_end[nb->nloops - 1] : 0;
    if (nb->ntp > start && nb->tp[nb->ntp - 1][0] == u && nb->tp[nb->ntp - 1][1] == v)
        return true; /* the join of two pieces of one loop */
    if (!grow((void **)&nb->tp, &nb->cap_tp, nb->ntp + 1, sizeof nb->tp[0])) {
        if (ip->scene)
            ip->scene->failed = true;
        return false;
    }
    nb->tp[nb->ntp][0] = u;
    nb->tp[nb->ntp][1] = v;
    nb->ntp++;
    return true;
}

void interp_pwlcurve(interp *ip, const rgl_cmd *cmd)
{
    struct interp_nurbs *nb = ip->st.nurbs;
    if (!nb || !nb->in_trim) {
        interp_diag(ip, DIAG_IGNORED, "gluPwlCurve outside gluBeginTrim/gluEndTrim");
        return;
    }
    int64_t count = rgl_arg_i(&cmd->arg[1], 0);
    GLenum type = arg_enum(cmd, 4);
    uint32_t k = type == GLU_MAP1_TRIM_2 ? 2 : type == GLU_MAP1_TRIM_3 ? 3 : 0;
    if (k == 0 || count < 2 || count > NURBS_MAX_TRIM) {
        interp_diag(ip, DIAG_IGNORED, "gluPwlCurve: bad type or count ignored");
        return;
    }
    double *v = blob_floats(ip, &cmd->arg[2], (size_t)count * k, "trim points");
    if (!v)
        return;
    for (int64_t i = 0; i < count; i++) {
        double w = k == 3 ? v[i * 3 + 2] : 1;
        if (w == 0 || !trim_add(ip, nb, v[i * k] / w, v[i * k + 1] / w))
            break;
    }
    tr_free(v);
}

void interp_nurbscurve(interp *ip, const rgl_cmd *cmd)
{
    struct interp_nurbs *nb = ip->st.nurbs;
    GLenum type = arg_enum(cmd, 6);
    bool trim = type == GLU_MAP1_TRIM_2 || type == GLU_MAP1_TRIM_3;
    if (!nb || (trim ? !nb->in_trim : nb->open != N_CURVE)) {
        interp_diag(ip, DIAG_IGNORED, "gluNurbsCurve outside gluBeginCurve or gluBeginTrim, or "
                                      "of a type that does not belong there");
        return;
    }
    uint32_t k = piece_k(type, false);
    int64_t nk = rgl_arg_i(&cmd->arg[1], 0), order = rgl_arg_i(&cmd->arg[5], 0);
    if (k == 0 || order < 1 || order > NURBS_MAX_ORDER || nk < 2 * order || nk > NURBS_MAX_TRIM) {
        interp_diag(ip, DIAG_IGNORED, "gluNurbsCurve: bad type, order or knot count ignored");
        return;
    }
    int n = (int)(nk - order);
    double *kn = blob_floats(ip, &cmd->arg[2], (size_t)nk, "knots");
    double *pts = kn ? blob_floats(ip, &cmd->arg[4], (size_t)n * k, "control points") : NULL;
    if (!kn || !pts || !knots_ok(kn, (int)nk)) {
        if (kn && pts)
            interp_diag(ip, DIAG_IGNORED, "gluNurbsCurve: decreasing knots ignored");
        tr_free(kn);
        tr_free(pts);
        return;
    }
    if (trim) {
        /* Sampled into the open loop, in (u, v) = (x/w, y/w). */
        for (int s = order - 1; s < n; s++) {
            if (kn[s] >= kn[s + 1])
                continue;
            for (int i = 0; i <= NURBS_CURVE_STEPS; i++) {
                double t = kn[s] + (kn[s + 1] - kn[s]) * i / NURBS_CURVE_STEPS, p[3];
                if (!interp_nurbs_curve_at(pts, k, kn, n, (int)order, t, p, NULL))
                    continue;
                double w = k == 3 ? p[2] : 1;
                if (w != 0 && !trim_add(ip, nb, p[0] / w, p[1] / w))
                    break;
            }
        }
        tr_free(kn);
        tr_free(pts);
        return;
    }
    if (nb->npieces >= NURBS_MAX_PIECES) {
        interp_diag(ip, DIAG_LIMIT, "GLU NURBS curve of over %d pieces: the rest dropped",
                    NURBS_MAX_PIECES);
        tr_free(kn);
        tr_free(pts);
        return;
    }
    nb->piece[nb->npieces++] = (nurbs_piece){type, k, {(int)order, 1}, {n, 1}, {kn, NULL}, pts};
}

void interp_nurbssurface(interp *ip, const rgl_cmd *cmd)
{
    struct interp_nurbs *nb = ip->st.nurbs;
    if (!nb || nb->open != N_SURFACE || nb->in_trim) {
        interp_diag(ip, DIAG_IGNORED, "gluNurbsSurface outside gluBeginSurface/gluEndSurface");
        return;
    }
    GLenum type = arg_enum(cmd, 10);
    uint32_t k = piece_k(type, true);
    int64_t nk[2] = {rgl_arg_i(&cmd->arg[1], 0), rgl_arg_i(&cmd->arg[3], 0)};
    int64_t order[2] = {rgl_arg_i(&cmd->arg[8], 0), rgl_arg_i(&cmd->arg[9], 0)};
    for (int d = 0; d < 2; d++) {
        if (k == 0 || order[d] < 1 || order[d] > NURBS_MAX_ORDER || nk[d] < 2 * order[d] ||
            nk[d] > NURBS_MAX_STEPS * 4) {
            interp_diag(ip, DIAG_IGNORED, "gluNurbsSurface: bad type, order or knot count "
                                          "ignored");
            return;
        }
    }
    int n[2] = {(int)(nk[0] - order[0]), (int)(nk[1] - order[1])};
    if ((uint64_t)n[0] * (uint64_t)n[1] > (1u << 20)) {
        interp_diag(ip, DIAG_LIMIT, "gluNurbsSurface of over 2^20 control points skipped");
        return;
    }
    double *kn0 = blob_floats(ip, &cmd->arg[2], (size_t)nk[0], "knots");
    double *kn1 = kn0 ? blob_floats(ip, &cmd->arg[4], (size_t)nk[1], "knots") : NULL;
    double *pts = kn1 ? blob_floats(ip, &cmd->arg[7], (size_t)n[0] * (size_t)n[1] * k,
                                    "control points")
                      : NULL;
    if (!pts || !knots_ok(kn0, (int)nk[0]) || !knots_ok(kn1, (int)nk[1]) ||
        nb->npieces >= NURBS_MAX_PIECES) {
        if (pts)
            interp_diag(ip, DIAG_IGNORED, "gluNurbsSurface: decreasing knots, or over %d "
                                          "pieces, ignored", NURBS_MAX_PIECES);
        tr_free(kn0);
        tr_free(kn1);
        tr_free(pts);
        return;
    }
    nb->piece[nb->npieces++] =
        (nurbs_piece){type, k, {(int)order[0], (int)order[1]}, {n[0], n[1]}, {kn0, kn1}, pts};
}

/* ---- Drawing ----------------------------------------------------------------------- */

/* The attribute pieces of the open shape, by role; vertex is the last
 * VERTEX_4 or VERTEX_3 piece (GLU keeps one of each type, the last given). */
typedef struct nurbs_roles {
    const nurbs_piece *vertex, *normal, *color, *tex;
} nurbs_roles;

static nurbs_roles roles_of(const struct interp_nurbs *nb, bool surface)
{
    nurbs_roles r = {0};
    GLenum base = surface ? GL_MAP2_COLOR_4 : GL_MAP1_COLOR_4;
    for (int i = 0; i < nb->npieces; i++) {
        const nurbs_piece *p = &nb->piece[i];
        switch (p->type - base) {
        case 0: r.color = p; break;                       /* COLOR_4 */
        case 2: r.normal = p; break;                      /* NORMAL */
        case 3: case 4: case 5: case 6:                   /* TEXTURE_COORD_1..4 */
            if (!r.tex || p->k >= r.tex->k)
                r.tex = p;
            break;
        case 7: case 8:                                   /* VERTEX_3, VERTEX_4 */
            if (!r.vertex || p->k >= r.vertex->k)
                r.vertex = p;
            break;
        default: break;                                   /* INDEX: not drawn */
        }
    }
    return r;
}

/* A piece at (u, v); a piece whose domain differs is evaluated at the same
 * parameters clamped to its own (GLU requires them to agree). */
static bool piece_at(const nurbs_piece *p, double u, double v, double *out, double *du,
                     double *dv)
{
    if (p->n[1] == 1 && p->order[1] == 1 && !p->knots[1])
        return interp_nurbs_curve_at(p->pts, p->k, p->knots[0], p->n[0], p->order[0], u, out, du);
    return interp_nurbs_surface_at(p->pts, p->k, p->knots[0], p->n[0], p->order[0], p->knots[1],
                                   p->n[1], p->order[1], u, v, out, du, dv);
}

/* A vertex of the shape: position (homogeneous), and the normal, colour
 * and texture coordinates its pieces give it (has_*: else the current
 * ones). */
typedef struct nurbs_node {
    double pos[4];
    float normal[3], color[4], tex[4];
    bool ok, has_normal, has_color, has_tex;
} nurbs_node;

/* The vertex at (u, v), as glEvalCoord computes it. */
static nurbs_node node_at(const interp *ip, const nurbs_roles *r, bool surface, double u,
                          double v)
{
    const gl_attribs *a = &ip->st.a;
    nurbs_node n;
    memset(&n, 0, sizeof n);
    double val[4], du[4], dv[4];
    if (r->color && piece_at(r->color, u, v, val, NULL, NULL)) {
        n.has_color = true;
        for (int c = 0; c < 4; c++)
            n.color[c] = (float)val[c];
    }
    if (r->normal && piece_at(r->normal, u, v, val, NULL, NULL)) {
        n.has_normal = true;
        for (int c = 0; c < 3; c++)
            n.normal[c] = (float)val[c];
    }
    if (r->tex && piece_at(r->tex, u, v, val, NULL, NULL)) {
        static const float def[4] = {0, 0, 0, 1};
        n.has_tex = true;
        for (uint32_t c = 0; c < 4; c++)
            n.tex[c] = c < r->tex->k ? (float)val[c] : def[c];
    }
    bool autonormal = surface && !r->normal && a->caps[INTERP_CAP_AUTO_NORMAL];
    if (!piece_at(r->vertex, u, v, val, autonormal ? du : NULL, autonormal ? dv : NULL))
        return n;
    uint32_t k = r->vertex->k;
    double w = k == 4 ? val[3] : 1;
    if (autonormal) {
        /* As GL_AUTO_NORMAL: dp/du x dp/dv of (x/w, y/w, z/w), here scaled
         * by w^2 (the same direction). */
        if (k == 4) {
            for (int c = 0; c < 3; c++) {
                du[c] = du[c] * w - du[3] * val[c];
                dv[c] = dv[c] * w - dv[3] * val[c];
            }
        }
        double nn[3] = {du[1] * dv[2] - du[2] * dv[1], du[2] * dv[0] - du[0] * dv[2],
                        du[0] * dv[1] - du[1] * dv[0]};
        double len = sqrt(nn[0] * nn[0] + nn[1] * nn[1] + nn[2] * nn[2]);
        n.has_normal = true;
        for (int c = 0; c < 3; c++)
            n.normal[c] = (float)(len > 0 ? nn[c] / len : nn[c]);
    }
    n.pos[0] = val[0];
    n.pos[1] = val[1];
    n.pos[2] = val[2];
    n.pos[3] = w;
    n.ok = true;
    return n;
}

/* The point at t of the straight segment from p to q, as GL's
 * interpolation along a triangle's edge gives it. */
static nurbs_node node_lerp(const nurbs_node *p, const nurbs_node *q, double t)
{
    nurbs_node n = *p;
    n.ok = p->ok && q->ok;
    double s = 1 - t;
    for (int c = 0; c < 4; c++) {
        double pc = p->pos[c] / p->pos[3], qc = q->pos[c] / q->pos[3];
        n.pos[c] = s * pc + t * qc;
        n.color[c] = (float)(s * p->color[c] + t * q->color[c]);
        n.tex[c] = (float)(s * p->tex[c] + t * q->tex[c]);
    }
    double len = 0;
    for (int c = 0; c < 3; c++) {
        n.normal[c] = (float)(s * p->normal[c] + t * q->normal[c]);
        len += (double)n.normal[c] * n.normal[c];
    }
    len = sqrt(len);
    for (int c = 0; c < 3 && len > 0; c++)
        n.normal[c] = (float)(n.normal[c] / len);
    return n;
}

/* Issues the vertex as glEvalCoord does: its colour, normal and texture
 * coordinates reach the vertex only (the current values are restored). */
static void node_emit(interp *ip, const nurbs_node *n)
{
    if (!n->ok)
        return;
    gl_attribs *a = &ip->st.a;
    float color[4], normal[3], texcoord[4];
    gl_material material[2];
    memcpy(color, a->current.color, sizeof color);
    memcpy(normal, a->current.normal, sizeof normal);
    memcpy(texcoord, a->current.texcoord, sizeof texcoord);
    memcpy(material, a->lighting.material, sizeof material);
    if (n->has_color) {
        memcpy(a->current.color, n->color, sizeof color);
        if (a->caps[INTERP_CAP_COLOR_MATERIAL])
            interp_cm_colour(ip);
    }
    if (n->has_normal)
        memcpy(a->current.normal, n->normal, sizeof normal);
    if (n->has_tex)
        memcpy(a->current.texcoord, n->tex, sizeof texcoord);
    interp_add_vertex(ip, n->pos[0], n->pos[1], n->pos[2], n->pos[3]);
    memcpy(a->current.color, color, sizeof color);
    memcpy(a->current.normal, normal, sizeof normal);
    memcpy(a->current.texcoord, texcoord, sizeof texcoord);
    memcpy(a->lighting.material, material, sizeof material);
}

static void nurbs_vertex(interp *ip, const nurbs_roles *r, bool surface, double u, double v)
{
    nurbs_node n = node_at(ip, r, surface, u, v);
    node_emit(ip, &n);
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

/* The grid lines along axis d of the vertex piece: per non-empty knot
 * span, GLU_DOMAIN_DISTANCE's steps; else NURBS_SPAN_STEPS, or more where
 * the window positions xy (may be NULL) of the control points give a
 * control polygon of more pixels over GLU's tolerance; plus `extra` values
 * inside the domain; sorted, without repeats. Returns how many (0 on
 * failure), into *out (caller frees); *finer becomes true when that is
 * finer than GLU's steps as far as they are known. */
/* The window positions (x, y in pixels) of the vertex piece's control
 * points under the current matrices and viewport (or the object's
 * sampling matrices), or NULL (a point behind the eye, or out of memory):
 * what GLU_PATH_LENGTH measures. */
static double *window_points(const interp *ip, const nurbs_piece *p, const nurbs_props *pr)
{
    size_t n = (size_t)p->n[0] * (size_t)p->n[1];
    bool own = pr->own_matrices && pr->have_matrices;
    mat4 w = own ? interp_window_matrix(&pr->proj, pr->view)
                 : interp_window_matrix(interp_matrix(ip, INTERP_PROJ), ip->st.a.viewport.rect);
    mat4 m = mat4_mul(&w, own ? &pr->model : interp_matrix(ip, INTERP_MV));
    double *xy = tr_realloc(NULL, 2 * n * sizeof *xy);
    if (!xy)
        return NULL;
    for (size_t i = 0; i < n; i++) {
        const double *q = p->pts + i * p->k;
        double in[4] = {q[0], q[1], q[2], p->k == 4 ? q[3] : 1}, out[4];
        mat4_apply(&m, in, out);
        if (!(out[3] > 0) || !isfinite(out[0]) || !isfinite(out[1])) {
            tr_free(xy);
            return NULL;
        }
        xy[2 * i] = out[0] / out[3];
        xy[2 * i + 1] = out[1] / out[3];
    }
    return xy;
}

/* The longest window-space length, over the rows of points along axis d,
 * of the control polygon of knot span s: the curve there is no longer, so
 * len / tolerance steps keep each step within GLU_PATH_LENGTH's pixels. */
static double span_pixels(const nurbs_piece *p, const double *xy, int d, int s)
{
    int other = p->n[1 - d], first = s - p->order[d] + 1;
    double best = 0;
    for (int r = 0; r < other; r++) {
        double len = 0;
        for (int i = first; i < s; i++) {
            size_t a = d == 0 ? (size_t)i * (size_t)p->n[1] + (size_t)r
                              : (size_t)r * (size_t)p->n[1] + (size_t)i;
            size_t b = d == 0 ? a + (size_t)p->n[1] : a + 1;
            len += hypot(xy[2 * b] - xy[2 * a], xy[2 * b + 1] - xy[2 * a + 1]);
        }
        if (len > best)
            best = len;
    }
    return best;
}

static size_t grid_axis(const nurbs_piece *p, int d, const nurbs_props *pr, const double *xy,
                        const double *extra, size_t nextra, double **out, bool *finer)
{
    const double *kn = p->knots[d];
    int n = p->n[d], order = p->order[d];
    double lo = kn[order - 1], hi = kn[n];
    if (!(lo < hi))
        return 0;
    size_t cap = NURBS_MAX_STEPS + nextra + 2, m = 0;
    double *g = tr_realloc(NULL, cap * sizeof *g);
    if (!g)
        return 0;
    double per_unit = pr->method == GLU_DOMAIN_DISTANCE ? (d ? pr->vstep : pr->ustep) : 0;
    for (int s = order - 1; s < n && m < NURBS_MAX_STEPS; s++) {
        double len = kn[s + 1] - kn[s];
        if (len <= 0)
            continue;
        /* GLU's steps: by domain distance, or (the other methods, which
         * measure on screen) at most the control polygon's pixels over
         * the tolerance; without window positions, unknown (0). */
        double steps = per_unit > 0 ? ceil(per_unit * len)
                       : xy         ? ceil(span_pixels(p, xy, d, s) / pr->tolerance)
                                    : 0;
        /* GLU_DOMAIN_DISTANCE's steps are known: exactly those (GLU's own
         * grid, which GLU_OUTLINE_POLYGON shows); else at least 16. */
        double want = per_unit > 0 ? (steps > 1 ? steps : 1)
                                   : (steps > NURBS_SPAN_STEPS ? steps : NURBS_SPAN_STEPS);
        int st = want < NURBS_MAX_STEPS ? (int)want : NURBS_MAX_STEPS;
        if (st > steps)
            *finer = true; /* GLU's own sampling is coarser, or depends on the view */
        for (int i = 0; i < st && m < NURBS_MAX_STEPS; i++)
            g[m++] = kn[s] + len * i / st;
    }
    g[m++] = hi;
    for (size_t i = 0; i < nextra; i++)
        if (extra[i] > lo && extra[i] < hi)
            g[m++] = extra[i];
    qsort(g, m, sizeof *g, cmp_double);
    size_t w = 0;
    for (size_t i = 0; i < m; i++)
        if (w == 0 || g[i] - g[w - 1] > 1e-9 * (hi - lo))
            g[w++] = g[i];
    *out = g;
    return w;
}

/* The winding numbers of the trim loops around the centres of one row of
 * cells, at v, for centres cu[0..n) (ascending), into wn: a ray to +u
 * crosses each edge at most once, an edge going up (v rising) counts +1 to
 * the left of its crossing, one going down -1. One sort a row, so a hostile
 * number of edges costs rows x edges, not cells x edges. */
typedef struct crossing {
    double u;
    int d;
} crossing;

static int cmp_crossing(const void *a, const void *b)
{
    double x = ((const crossing *)a)->u, y = ((const crossing *)b)->u;
    return x < y ? -1 : x > y;
}

static void row_winding(const struct interp_nurbs *nb, double v, const double *cu, size_t n,
                        crossing *cr, uint8_t *in)
{
    size_t m = 0, start = 0;
    int total = 0;
    for (size_t l = 0; l < nb->nloops; start = nb->loop_end[l++]) {
        size_t end = nb->loop_end[l];
        for (size_t i = start; i < end; i++) {
            const double *a = nb->tp[i], *b = nb->tp[i + 1 < end ? i + 1 : start];
            int d = a[1] <= v && b[1] > v ? 1 : b[1] <= v && a[1] > v ? -1 : 0;
            if (!d)
                continue;
            cr[m].u = a[0] + (v - a[1]) * (b[0] - a[0]) / (b[1] - a[1]);
            cr[m++].d = d;
            total += d;
        }
    }
    qsort(cr, m, sizeof *cr, cmp_crossing);
    size_t p = 0;
    int left = 0; /* crossings at or left of the centre */
    for (size_t i = 0; i < n; i++) {
        while (p < m && cr[p].u <= cu[i])
            left += cr[p++].d;
        in[i] = total - left > 0;
    }
}

/* Counts n grid points against the frame's allowance (with evaluator
 * meshes and tessellated shapes); false, after a diagnostic, when over. */
static bool nurbs_budget(interp *ip, uint64_t n)
{
    if (ip->shape_facets + n > NURBS_FRAME_MAX_POINTS) {
        interp_diag(ip, DIAG_LIMIT, "GLU NURBS skipped: the frame's meshes and shapes exceed %u "
                                    "points", NURBS_FRAME_MAX_POINTS);
        return false;
    }
    ip->shape_facets += n;
    return true;
}

/* Trim-edge coordinates parallel to the axes: v of the edges along u
 * (axis 0 gets the u of edges along v). */
static size_t trim_axis_values(const struct interp_nurbs *nb, int d, double **out)
{
    *out = NULL;
    if (nb->ntp == 0)
        return 0;
    double *v = tr_realloc(NULL, nb->ntp * sizeof *v);
    if (!v)
        return 0;
    size_t m = 0, start = 0;
    for (size_t l = 0; l < nb->nloops; l++) {
        size_t end = nb->loop_end[l];
        for (size_t i = start; i < end && m < NURBS_MAX_STEPS; i++) {
            const double *a = nb->tp[i], *b = nb->tp[i + 1 < end ? i + 1 : start];
            if (a[d] == b[d] && a[1 - d] != b[1 - d])
                v[m++] = a[d];
        }
        start = end;
    }
    *out = v;
    return m;
}

static bool trims_oblique(const struct interp_nurbs *nb)
{
    size_t start = 0;
    for (size_t l = 0; l < nb->nloops; l++) {
        size_t end = nb->loop_end[l];
        for (size_t i = start; i < end; i++) {
            const double *a = nb->tp[i], *b = nb->tp[i + 1 < end ? i + 1 : start];
            if (a[0] != b[0] && a[1] != b[1])
                return true;
        }
        start = end;
    }
    return false;
}

/* Index of the grid line at x (within the merge tolerance), or -1. */
static long grid_find(const double *g, size_t n, double x)
{
    double tol = 1e-9 * (g[n - 1] - g[0]);
    size_t lo = 0, hi = n;
    while (lo < hi) {
        size_t mid = (lo + hi) / 2;
        if (g[mid] < x - tol)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo < n && fabs(g[lo] - x) <= tol ? (long)lo : -1;
}

/* The grid's vertices, nodes[j * ng[0] + i] at (g[0][i], g[1][j]). A grid
 * vertex on a trim edge (the edges parallel to an axis put grid lines
 * there) lies on the straight segment between the surface points of the
 * edge's ends, where GLU's triangles, which meet the trim only at its
 * points, draw the cut. */
static nurbs_node *grid_nodes(interp *ip, const struct interp_nurbs *nb, const nurbs_roles *r,
                              double *const g[2], const size_t ng[2])
{
    nurbs_node *nodes = tr_realloc(NULL, ng[0] * ng[1] * sizeof *nodes);
    if (!nodes)
        return NULL;
    for (size_t j = 0; j < ng[1]; j++)
        for (size_t i = 0; i < ng[0]; i++)
            nodes[j * ng[0] + i] = node_at(ip, r, true, g[0][i], g[1][j]);
    size_t start = 0;
    for (size_t l = 0; l < nb->nloops; start = nb->loop_end[l++]) {
        size_t end = nb->loop_end[l];
        for (size_t e = start; e < end; e++) {
            const double *a = nb->tp[e], *b = nb->tp[e + 1 < end ? e + 1 : start];
            int d = a[0] == b[0] ? 0 : a[1] == b[1] ? 1 : -1; /* the fixed coordinate */
            if (d < 0 || a[1 - d] == b[1 - d])
                continue;
            long line = grid_find(g[d], ng[d], a[d]);
            if (line < 0)
                continue;
            nurbs_node na = node_at(ip, r, true, a[0], a[1]), nbb = node_at(ip, r, true, b[0], b[1]);
            double lo = a[1 - d] < b[1 - d] ? a[1 - d] : b[1 - d];
            double hi = a[1 - d] < b[1 - d] ? b[1 - d] : a[1 - d];
            for (size_t m = 0; m < ng[1 - d]; m++) {
                double x = g[1 - d][m];
                if (x <= lo || x >= hi)
                    continue;
                size_t i = d == 0 ? (size_t)line : m, j = d == 0 ? m : (size_t)line;
                nodes[j * ng[0] + i] =
                    node_lerp(&na, &nbb, (x - a[1 - d]) / (b[1 - d] - a[1 - d]));
            }
        }
    }
    return nodes;
}

static void draw_surface(interp *ip, struct interp_nurbs *nb, const nurbs_props *pr)
{
    nurbs_roles r = roles_of(nb, true);
    if (!r.vertex)
        return; /* GLU draws nothing without a vertex piece */
    double *ex[2], *g[2] = {NULL, NULL};
    size_t nex[2], ng[2] = {0, 0};
    nurbs_node *nodes = NULL;
    uint8_t *in = NULL;
    bool finer = false;
    double *xy = pr->method == GLU_DOMAIN_DISTANCE ? NULL : window_points(ip, r.vertex, pr);
    for (int d = 0; d < 2; d++) {
        nex[d] = trim_axis_values(nb, d, &ex[d]);
        ng[d] = grid_axis(r.vertex, d, pr, xy, ex[d], nex[d], &g[d], &finer);
        tr_free(ex[d]);
    }
    tr_free(xy);
    if (ng[0] < 2 || ng[1] < 2)
        goto done;
    if ((uint64_t)ng[0] * ng[1] > NURBS_MAX_GRID) {
        interp_diag(ip, DIAG_LIMIT, "GLU NURBS surface of a %zu x %zu grid skipped: over %u "
                                    "points", ng[0], ng[1], NURBS_MAX_GRID);
        goto done;
    }
    if (!nurbs_budget(ip, (uint64_t)ng[0] * ng[1]))
        goto done;
    if (nb->nloops && trims_oblique(nb))
        interp_note(ip, DIAG_NOTE_NURBS_TRIM);
    if (finer)
        interp_note(ip, DIAG_NOTE_NURBS_SAMPLING);

    /* Which cells are drawn. */
    size_t cu = ng[0] - 1, cv = ng[1] - 1;
    in = tr_realloc(NULL, cu * cv);
    nodes = in ? grid_nodes(ip, nb, &r, g, ng) : NULL;
    if (!nodes) {
        if (ip->scene)
            ip->scene->failed = true;
        goto done;
    }
    if (!nb->nloops) {
        memset(in, 1, cu * cv);
    } else {
        double *centre = tr_realloc(NULL, cu * sizeof *centre);
        crossing *cr = tr_realloc(NULL, (nb->ntp ? nb->ntp : 1) * sizeof *cr);
        if (!centre || !cr) {
            tr_free(centre);
            tr_free(cr);
            if (ip->scene)
                ip->scene->failed = true;
            goto done;
        }
        for (size_t i = 0; i < cu; i++)
            centre[i] = (g[0][i] + g[0][i + 1]) / 2;
        for (size_t j = 0; j < cv; j++)
            row_winding(nb, (g[1][j] + g[1][j + 1]) / 2, centre, cu, cr, in + j * cu);
        tr_free(centre);
        tr_free(cr);
    }
#define NODE(i, j) (&nodes[(j) * ng[0] + (i)])
    if (pr->display == GLU_FILL) {
        if (interp_prim_begin(ip, GL_TRIANGLES)) {
            for (size_t j = 0; j < cv; j++) {
                for (size_t i = 0; i < cu; i++) {
                    if (!in[j * cu + i])
                        continue;
                    node_emit(ip, NODE(i, j));
                    node_emit(ip, NODE(i + 1, j));
                    node_emit(ip, NODE(i + 1, j + 1));
                    node_emit(ip, NODE(i, j));
                    node_emit(ip, NODE(i + 1, j + 1));
                    node_emit(ip, NODE(i, j + 1));
                }
            }
        }
        interp_prim_end(ip);
    } else if (pr->display == GLU_OUTLINE_POLYGON) {
        /* Untrimmed, GLU outlines its sampling grid; near trims, its own
         * triangles. */
        if (nb->nloops)
            interp_note(ip, DIAG_NOTE_NURBS_OUTLINE);
        /* Each drawn cell's edges, once: its lower and left ones, and its
         * upper and right ones where no drawn cell continues. */
        if (interp_prim_begin(ip, GL_LINES)) {
            for (size_t j = 0; j < cv; j++) {
                for (size_t i = 0; i < cu; i++) {
                    if (!in[j * cu + i])
                        continue;
                    node_emit(ip, NODE(i, j));
                    node_emit(ip, NODE(i + 1, j));
                    node_emit(ip, NODE(i, j));
                    node_emit(ip, NODE(i, j + 1));
                    if (j + 1 == cv || !in[(j + 1) * cu + i]) {
                        node_emit(ip, NODE(i, j + 1));
                        node_emit(ip, NODE(i + 1, j + 1));
                    }
                    if (i + 1 == cu || !in[j * cu + i + 1]) {
                        node_emit(ip, NODE(i + 1, j));
                        node_emit(ip, NODE(i + 1, j + 1));
                    }
                }
            }
        }
        interp_prim_end(ip);
    } else if (nb->nloops == 0) {
        /* GLU_OUTLINE_PATCH of an untrimmed surface: its four edges. */
        for (int side = 0; side < 4; side++) {
            int d = side & 1; /* the axis the edge runs along */
            size_t fixed = side < 2 ? 0 : ng[1 - d] - 1;
            if (interp_prim_begin(ip, GL_LINE_STRIP))
                for (size_t m = 0; m < ng[d]; m++)
                    node_emit(ip, d ? NODE(fixed, m) : NODE(m, fixed));
            interp_prim_end(ip);
        }
    } else {
        /* GLU_OUTLINE_PATCH of a trimmed surface: each trim loop, straight
         * between its points on the surface. */
        for (size_t l = 0, start = 0; l < nb->nloops; start = nb->loop_end[l++]) {
            if (interp_prim_begin(ip, GL_LINE_LOOP))
                for (size_t e = start; e < nb->loop_end[l]; e++)
                    nurbs_vertex(ip, &r, true, nb->tp[e][0], nb->tp[e][1]);
            interp_prim_end(ip);
        }
    }
#undef NODE
done:
    tr_free(nodes);
    tr_free(in);
    tr_free(g[0]);
    tr_free(g[1]);
}

static void draw_curve(interp *ip, struct interp_nurbs *nb, const nurbs_props *pr)
{
    nurbs_roles r = roles_of(nb, false);
    if (!r.vertex)
        return;
    double *g = NULL;
    bool finer = false;
    double *xy = pr->method == GLU_DOMAIN_DISTANCE ? NULL : window_points(ip, r.vertex, pr);
    size_t ng = grid_axis(r.vertex, 0, pr, xy, NULL, 0, &g, &finer);
    tr_free(xy);
    if (finer && ng >= 2)
        interp_note(ip, DIAG_NOTE_NURBS_SAMPLING);
    if (ng >= 2 && nurbs_budget(ip, ng) && interp_prim_begin(ip, GL_LINE_STRIP))
        for (size_t i = 0; i < ng; i++)
            nurbs_vertex(ip, &r, false, g[i], 0);
    if (ng >= 2)
        interp_prim_end(ip);
    tr_free(g);
}

void interp_nurbsend(interp *ip, const rgl_cmd *cmd)
{
    struct interp_nurbs *nb = ip->st.nurbs;
    uint32_t op = cmd->opcode;
    if (op == RGL_OP_EndTrim) {
        if (!nb || !nb->in_trim) {
            interp_diag(ip, DIAG_IGNORED, "gluEndTrim without gluBeginTrim");
            return;
        }
        nb->in_trim = false;
        size_t start = nb->nloops ? nb->loop_end[nb->nloops - 1] : 0;
        /* A closed loop repeats its first point last: one is enough. */
        if (nb->ntp > start + 1 && nb->tp[nb->ntp - 1][0] == nb->tp[start][0] &&
            nb->tp[nb->ntp - 1][1] == nb->tp[start][1])
            nb->ntp--;
        if (nb->ntp < start + 3) { /* no area: nothing to cut */
            nb->ntp = start;
            return;
        }
        if (!grow((void **)&nb->loop_end, &nb->cap_loops, nb->nloops + 1, sizeof(size_t))) {
            if (ip->scene)
                ip->scene->failed = true;
            nb->ntp = start;
            return;
        }
        nb->loop_end[nb->nloops++] = nb->ntp;
        return;
    }
    int want = op == RGL_OP_EndSurface ? N_SURFACE : N_CURVE;
    if (!nb || nb->open != want) {
        interp_diag(ip, DIAG_IGNORED, "%s without its begin",
                    want == N_SURFACE ? "gluEndSurface" : "gluEndCurve");
        return;
    }
    if (interp_reject_in_begin(ip)) {
        pieces_clear(nb);
        return;
    }
    nurbs_props pr = props_of(ip, nb->open_id);
    if (pr.mode == GLU_NURBS_TESSELLATOR) {
        /* GLU hands the pieces to the program's callbacks, whose GL calls
         * are recorded as the program's own. */
        interp_note(ip, DIAG_NOTE_NURBS_TESSELLATOR);
    } else if (want == N_SURFACE) {
        draw_surface(ip, nb, &pr);
    } else {
        draw_curve(ip, nb, &pr);
    }
    pieces_clear(nb);
}
