/* interp_matrix.c: matrix modes and stacks, every transform call, the
 * recorder's resolved matrices (@Matrix), glViewport and glDepthRange.
 *
 * Stacks have GL's depths (modelview 32, projection 2, texture 2); a push
 * on a full stack or a pop of the last entry is GL_STACK_OVERFLOW /
 * GL_STACK_UNDERFLOW and is skipped. Matrices are kept in double and
 * compared at float precision, the precision GL keeps them in.
 */
#include "interp_internal.h"

static int mode_index(GLenum mode)
{
    switch (mode) {
    case GL_MODELVIEW: return INTERP_MV;
    case GL_PROJECTION: return INTERP_PROJ;
    case GL_TEXTURE: return INTERP_TEX;
    default: return -1;
    }
}

static mat4 *stack_base(gl_state *st, int mode, int *max)
{
    switch (mode) {
    case INTERP_PROJ:
        *max = INTERP_PROJECTION_DEPTH;
        return st->projection;
    case INTERP_TEX:
        *max = INTERP_TEXTURE_DEPTH;
        return st->texture;
    default:
        *max = INTERP_MODELVIEW_DEPTH;
        return st->modelview;
    }
}

static mat4 *current(interp *ip)
{
    int max, mode = mode_index(ip->st.a.transform.matrix_mode);
    mat4 *base = stack_base(&ip->st, mode < 0 ? INTERP_MV : mode, &max);
    return &base[ip->st.depth[mode < 0 ? INTERP_MV : mode]];
}

/* current = current * m, as glMultMatrix. */
static void mult(interp *ip, const mat4 *m)
{
    mat4 *c = current(ip);
    *c = mat4_mul(c, m);
}

static void load16(const rgl_cmd *cmd, mat4 *m)
{
    for (int i = 0; i < 16; i++)
        m->m[i] = rgl_arg_f(&cmd->arg[cmd->nargs - 1], (uint32_t)i);
}

void interp_matrixmode(interp *ip, const rgl_cmd *cmd)
{
    GLenum mode = arg_enum(cmd, 0);
    if (mode_index(mode) < 0) {
        interp_bad_enum(ip, "matrix mode", mode);
        return;
    }
    ip->st.a.transform.matrix_mode = mode;
}

void interp_loadidentity(interp *ip, const rgl_cmd *cmd)
{
    (void)cmd;
    *current(ip) = mat4_identity();
}

void interp_pushmatrix(interp *ip, const rgl_cmd *cmd)
{
    (void)cmd;
    int max, mode = mode_index(ip->st.a.transform.matrix_mode);
    mat4 *base = stack_base(&ip->st, mode, &max);
    int *d = &ip->st.depth[mode];
    if (*d + 1 >= max) {
        interp_diag(ip, DIAG_GL_STACK_OVERFLOW, "matrix stack overflow (depth %d)", max);
        return;
    }
    base[*d + 1] = base[*d];
    (*d)++;
}

void interp_popmatrix(interp *ip, const rgl_cmd *cmd)
{
    (void)cmd;
    int mode = mode_index(ip->st.a.transform.matrix_mode);
    int *d = &ip->st.depth[mode];
    if (*d <= 0) {
        interp_diag(ip, DIAG_GL_STACK_UNDERFLOW, "matrix stack underflow");
        return;
    }
    (*d)--;
}

void interp_translate(interp *ip, const rgl_cmd *cmd)
{
    mat4 m = mat4_translate(arg_num(&cmd->arg[0]), arg_num(&cmd->arg[1]), arg_num(&cmd->arg[2]));
    mult(ip, &m);
}

void interp_rotate(interp *ip, const rgl_cmd *cmd)
{
    mat4 m = mat4_rotate(arg_num(&cmd->arg[0]), arg_num(&cmd->arg[1]), arg_num(&cmd->arg[2]),
                         arg_num(&cmd->arg[3]));
    mult(ip, &m);
}

void interp_scale(interp *ip, const rgl_cmd *cmd)
{
    mat4 m = mat4_scale(arg_num(&cmd->arg[0]), arg_num(&cmd->arg[1]), arg_num(&cmd->arg[2]));
    mult(ip, &m);
}

void interp_loadmatrix(interp *ip, const rgl_cmd *cmd)
{
    load16(cmd, current(ip));
}

void interp_multmatrix(interp *ip, const rgl_cmd *cmd)
{
    mat4 m;
    load16(cmd, &m);
    mult(ip, &m);
}

void interp_loadtransposematrix(interp *ip, const rgl_cmd *cmd)
{
    mat4 m;
    load16(cmd, &m);
    *current(ip) = mat4_transpose(&m);
}

void interp_multtransposematrix(interp *ip, const rgl_cmd *cmd)
{
    mat4 m, t;
    load16(cmd, &m);
    t = mat4_transpose(&m);
    mult(ip, &t);
}

/* @Matrix: the matrix the recorder read back from the live context before a
 * draw. It replaces the top of that mode's stack: GL's own matrix wins over
 * whatever the recorded calls computed (the program may have called the
 * real glTranslatef, which the recorder never saw). */
void interp_resolvedmatrix(interp *ip, const rgl_cmd *cmd)
{
    GLenum mode = arg_enum(cmd, 0);
    int i = mode_index(mode), max;
    if (i < 0) {
        interp_diag(ip, DIAG_IGNORED, "@Matrix for unknown matrix mode 0x%x ignored", mode);
        return;
    }
    mat4 *base = stack_base(&ip->st, i, &max);
    load16(cmd, &base[ip->st.depth[i]]);
}

void interp_frustum(interp *ip, const rgl_cmd *cmd)
{
    double v[6];
    for (int i = 0; i < 6; i++)
        v[i] = arg_num(&cmd->arg[i]);
    if (!mat4_frustum_valid(v[0], v[1], v[2], v[3], v[4], v[5])) {
        interp_bad_value(ip, "glFrustum with near or far <= 0, or an empty range");
        return;
    }
    mat4 m = mat4_frustum(v[0], v[1], v[2], v[3], v[4], v[5]);
    mult(ip, &m);
}

static void ortho(interp *ip, const double v[6])
{
    if (!mat4_ortho_valid(v[0], v[1], v[2], v[3], v[4], v[5])) {
        interp_bad_value(ip, "glOrtho with an empty range");
        return;
    }
    mat4 m = mat4_ortho(v[0], v[1], v[2], v[3], v[4], v[5]);
    mult(ip, &m);
}

void interp_ortho(interp *ip, const rgl_cmd *cmd)
{
    double v[6];
    for (int i = 0; i < 6; i++)
        v[i] = arg_num(&cmd->arg[i]);
    ortho(ip, v);
}

/* gluOrtho2D is glOrtho(left, right, bottom, top, -1, 1). */
void interp_ortho2d(interp *ip, const rgl_cmd *cmd)
{
    double v[6];
    for (int i = 0; i < 4; i++)
        v[i] = arg_num(&cmd->arg[i]);
    v[4] = -1;
    v[5] = 1;
    ortho(ip, v);
}

/* gluPerspective and gluLookAt end in glMultMatrix: inside glBegin they
 * fail there (the central check in interp_exec already skipped them). */
void interp_perspective(interp *ip, const rgl_cmd *cmd)
{
    mat4 m;
    if (!mat4_perspective(arg_num(&cmd->arg[0]), arg_num(&cmd->arg[1]), arg_num(&cmd->arg[2]),
                          arg_num(&cmd->arg[3]), &m))
        return; /* GLU returns silently */
    mult(ip, &m);
}

void interp_lookat(interp *ip, const rgl_cmd *cmd)
{
    double v[9];
    for (int i = 0; i < 9; i++)
        v[i] = arg_num(&cmd->arg[i]);
    mat4 m = mat4_lookat(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8]);
    mult(ip, &m);
    /* What follows is drawn in the world gluLookAt looked at: kept for the
     * camera and light overrides (look.c). */
    if (ip->scene && !ip->scene->have_view && ip->st.a.transform.matrix_mode == GL_MODELVIEW) {
        ip->scene->have_view = true;
        ip->scene->view = *current(ip);
        for (int k = 0; k < 3; k++)
            ip->scene->view_look_at[k] = v[3 + k];
    }
}

void interp_viewport(interp *ip, const rgl_cmd *cmd)
{
    int64_t x = cmd->arg[0].v.i, y = cmd->arg[1].v.i;
    int64_t w = cmd->arg[2].v.i, h = cmd->arg[3].v.i;
    if (w < 0 || h < 0) {
        interp_bad_value(ip, "negative viewport size");
        return;
    }
    /* GL clamps the size to GL_MAX_VIEWPORT_DIMS silently. */
    if (w > INTERP_MAX_VIEWPORT)
        w = INTERP_MAX_VIEWPORT;
    if (h > INTERP_MAX_VIEWPORT)
        h = INTERP_MAX_VIEWPORT;
    if (x < INT32_MIN / 2 || x > INT32_MAX / 2 || y < INT32_MIN / 2 || y > INT32_MAX / 2) {
        interp_bad_value(ip, "viewport position out of range");
        return;
    }
    int32_t *r = ip->st.a.viewport.rect;
    r[0] = (int32_t)x;
    r[1] = (int32_t)y;
    r[2] = (int32_t)w;
    r[3] = (int32_t)h;
}

static double clamp01d(double v) { return v > 0 ? (v < 1 ? v : 1) : 0; }

void interp_depthrange(interp *ip, const rgl_cmd *cmd)
{
    ip->st.a.viewport.near = clamp01d(arg_num(&cmd->arg[0]));
    ip->st.a.viewport.far = clamp01d(arg_num(&cmd->arg[1]));
}

mat4 interp_window_matrix(const mat4 *proj, const int32_t vp[4])
{
    /* NDC -> window x, y (z kept): x_w = x + (x_ndc + 1) w / 2. */
    mat4 v = mat4_identity();
    v.m[0] = vp[2] / 2.0;
    v.m[5] = vp[3] / 2.0;
    v.m[12] = vp[0] + vp[2] / 2.0;
    v.m[13] = vp[1] + vp[3] / 2.0;
    return mat4_mul(&v, proj);
}
