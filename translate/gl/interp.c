/* interp.c: the interpreter's core: dispatch, the run loop, diagnostics,
 * GL's initial state, glEnable/glDisable and the attribute stack.
 *
 * The dispatch table is generated from format/commands.def: each row's
 * opcode maps to interp_<handler>. Checks that apply to every command (the
 * calls GL forbids between glBegin and glEnd) happen here, before the
 * handler runs, as Mesa validates in its entry points.
 */
#include "interp_internal.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "talloc.h"
#include "wire.h"

typedef void (*interp_handler)(interp *ip, const rgl_cmd *cmd);

static const interp_handler dispatch[] = {
#define RGL_CMD(op, api, gen, name, handler, ...) [RGL_OP_##name] = interp_##handler,
#include "commands.def"
#undef RGL_CMD
};
#define DISPATCH_SIZE (sizeof dispatch / sizeof dispatch[0])

/* Commands GL accepts between glBegin and glEnd (GL 1.x section 2.6.3),
 * plus the recorder's own records and the raygl frame calls, which are
 * not GL calls. */
static bool allowed_in_begin(const char *handler)
{
    static const char *const ok[] = {
        "vertex",       "normal",    "color",     "texcoord",       "edgeflag",   "end",
        "material",     "calllist",  "calllists", "arrayelement",   "resolvedmatrix",
        "arraydata",    "framebegin", "frameend", "swapbuffers",
        "snapshot",     "notrecorded", "evalcoord1", "evalcoord2", "evalpoint1", "evalpoint2",
        "multitexcoord", "fogcoord", "secondarycolor",
    };
    for (size_t i = 0; i < sizeof ok / sizeof ok[0]; i++)
        if (strcmp(handler, ok[i]) == 0)
            return true;
    return false;
}

/* Fills the per-interpreter table of commands allowed inside glBegin (kept
 * per interpreter: no shared mutable state between worker threads). */
static void init_begin_ok(uint8_t *begin_ok)
{
    size_t n;
    const rgl_cmd_info *const *all = rgl_cmd_info_all(&n);
    memset(begin_ok, 0, DISPATCH_SIZE);
    for (size_t i = 0; i < n; i++)
        if (all[i]->opcode < DISPATCH_SIZE)
            begin_ok[all[i]->opcode] = allowed_in_begin(all[i]->handler);
}

/* ---- Initial state (GL 1.x state tables, section 6.2) ---------------------- */

static const uint8_t cap_defaults[INTERP_CAP_COUNT] = {
#define CAP(name, def, group) def,
#include "caps.def"
#undef CAP
};

static const uint32_t cap_groups[INTERP_CAP_COUNT] = {
#define CAP(name, def, group) group,
#include "caps.def"
#undef CAP
};

int interp_cap_index(GLenum cap)
{
    switch (cap) {
#define CAP(name, def, group) \
    case GL_##name:           \
        return INTERP_CAP_##name;
#include "caps.def"
#undef CAP
    default:
        return -1;
    }
}

static void set4(float *d, float a, float b, float c, float e)
{
    d[0] = a;
    d[1] = b;
    d[2] = c;
    d[3] = e;
}

void interp_default_state(gl_state *st)
{
    /* The heap parts are reset by their owners (interp_reset). */
    struct interp_textures *tex = st->tex;
    struct interp_eval *eval = st->eval;
    struct interp_nurbs *nurbs = st->nurbs;
    struct interp_lists *lists = st->lists;
    memset(st, 0, sizeof *st);
    st->tex = tex;
    st->eval = eval;
    st->nurbs = nurbs;
    st->lists = lists;
    gl_attribs *a = &st->a;

    set4(a->current.color, 1, 1, 1, 1);
    a->current.normal[2] = 1;
    set4(a->current.texcoord, 0, 0, 0, 1);
    a->current.edge_flag = true;
    set4(a->current.raster_color, 1, 1, 1, 1);
    a->current.raster_pos[3] = 1;
    a->current.raster_valid = true;
    a->pixel.zoom[0] = a->pixel.zoom[1] = 1;
    set4(a->pixel.scale, 1, 1, 1, 1);
    for (int k = 0; k < 10; k++)
        a->pixel.map_size[k] = 1;
    memcpy(a->caps, cap_defaults, sizeof a->caps);

    for (int d = 0; d < 2; d++) { /* glMapGrid: 1 partition of [0, 1] */
        a->eval.grid_n[d][0] = a->eval.grid_n[d][1] = 1;
        a->eval.grid[d][0][1] = a->eval.grid[d][1][1] = 1;
    }
    st->render_mode = GL_RENDER;
    st->select_size = st->feedback_size = -1;
    a->lighting.shade_model = GL_SMOOTH;
    for (int f = 0; f < 2; f++) {
        gl_material *m = &a->lighting.material[f];
        set4(m->ambient, 0.2f, 0.2f, 0.2f, 1);
        set4(m->diffuse, 0.8f, 0.8f, 0.8f, 1);
        set4(m->specular, 0, 0, 0, 1);
        set4(m->emission, 0, 0, 0, 1);
        m->shininess = 0;
    }
    a->lighting.color_material_face = GL_FRONT_AND_BACK;
    a->lighting.color_material_mode = GL_AMBIENT_AND_DIFFUSE;
    for (int i = 0; i < INTERP_MAX_LIGHTS; i++) {
        gl_light *l = &a->lighting.light[i];
        set4(l->ambient, 0, 0, 0, 1);
        if (i == 0) {
            set4(l->diffuse, 1, 1, 1, 1);
            set4(l->specular, 1, 1, 1, 1);
        } else {
            set4(l->diffuse, 0, 0, 0, 1);
            set4(l->specular, 0, 0, 0, 1);
        }
        set4(l->position, 0, 0, 1, 0);
        l->spot_direction[2] = -1;
        l->spot_exponent = 0;
        l->spot_cutoff = 180;
        l->attenuation[0] = 1;
    }
    set4(a->lighting.model_ambient, 0.2f, 0.2f, 0.2f, 1);

    a->polygon.front_face = GL_CCW;
    a->polygon.cull_mode = GL_BACK;
    a->polygon.mode[0] = a->polygon.mode[1] = GL_FILL;
    a->line.width = 1;
    a->point.size = 1;
    a->point.size_max = 1024; /* Mesa's largest point, interp_pointsize's limit */
    a->point.sprite_origin = GL_UPPER_LEFT;
    a->point.fade_threshold = 1;
    a->point.atten[0] = 1;
    a->lighting.provoking = GL_LAST_VERTEX_CONVENTION;
    /* The window size is unknown here; the recorder's snapshot (or the
     * program) sets the viewport. */
    a->viewport.rect[2] = 640;
    a->viewport.rect[3] = 480;
    a->viewport.near = 0;
    a->viewport.far = 1;
    a->transform.matrix_mode = GL_MODELVIEW;
    a->color_buffer.blend_src = GL_ONE;
    a->color_buffer.blend_dst = GL_ZERO;
    a->color_buffer.blend_equation = GL_FUNC_ADD;
    a->color_buffer.blend_src_alpha = GL_ONE;
    a->color_buffer.blend_dst_alpha = GL_ZERO;
    a->color_buffer.blend_equation_alpha = GL_FUNC_ADD;
    a->color_buffer.logic_op = GL_COPY;
    a->color_buffer.alpha_func = GL_ALWAYS;
    for (int i = 0; i < 4; i++)
        a->color_buffer.mask[i] = true;
    for (int f = 0; f < 2; f++) {
        struct gl_stencil_face *sf = &a->stencil.face[f];
        sf->func = GL_ALWAYS;
        sf->fail = sf->zfail = sf->zpass = GL_KEEP;
        sf->value_mask = sf->write_mask = 0xffffffffu;
    }
    a->line.stipple_factor = 1;
    a->line.stipple_pattern = 0xffff;
    memset(a->polygon.stipple, 0xff, sizeof a->polygon.stipple);
    a->depth.func = GL_LESS;
    a->depth.mask = true;
    a->depth.clear = 1;
    a->fog.mode = GL_EXP;
    a->color_buffer.draw_buffer = INTERP_DRAW_BUFFER_DEFAULT;
    a->fog.coord_src = GL_FRAGMENT_DEPTH;
    a->fog.distance = GL_EYE_PLANE_ABSOLUTE_NV; /* Mesa's; NV_fog_distance says GL_EYE_RADIAL_NV may be */
    a->lighting.color_control = GL_SINGLE_COLOR;
    a->fog.density = 1;
    a->fog.start = 0;
    a->fog.end = 1;
    a->hint.perspective = a->hint.point = a->hint.line = a->hint.polygon = a->hint.fog =
        GL_DONT_CARE;
    a->texture.env_mode = GL_MODULATE;
    interp_combine_defaults(&a->texture);
    for (int i = 0; i < 4; i++) {
        a->texture.gen_mode[i] = GL_EYE_LINEAR;
        for (int k = 0; k < 4; k++)
            a->texture.obj_plane[i][k] = a->texture.eye_plane[i][k] = i == k && i < 2;
    }

    for (int i = 0; i < INTERP_NMODES; i++)
        st->depth[i] = 0;
    st->modelview[0] = mat4_identity();
    st->projection[0] = mat4_identity();
    st->texture[0] = mat4_identity();
    interp_multitex_defaults(st);
}

/* ---- Life cycle ---------------------------------------------------------------- */

interp *interp_create(scene *out, diag_log *log)
{
    interp *ip = tr_realloc(NULL, sizeof *ip);
    if (!ip)
        return NULL;
    memset(ip, 0, sizeof *ip);
    ip->begin_ok = tr_realloc(NULL, DISPATCH_SIZE);
    if (!ip->begin_ok) {
        tr_free(ip);
        return NULL;
    }
    init_begin_ok(ip->begin_ok);
    ip->scene = out;
    ip->log = log;
    interp_reset(ip);
    return ip;
}

void interp_destroy(interp *ip)
{
    if (!ip)
        return;
    interp_lists_free(ip);
    unrec_finish(&ip->unrecorded);
    tr_free(ip->begin_ok);
    tr_free(ip->edge);
    tr_free(ip->relit_col);
    tr_free(ip->relit_in);
    tr_free(ip->relit_need);
    tr_free(ip->relit_tris);
    tr_free(ip->relit_copy);
    tr_free(ip->fogz);
    tr_free(ip->vmat.mats);
    tr_free(ip->clipv);
    tr_free(ip->ras_runs);
    tr_free(ip->ras_pieces);
    interp_textures_free(ip);
    interp_pixels_free(ip);
    interp_eval_free(ip);
    interp_nurbs_free(ip);
    interp_dest_free(ip);
    interp_sprites_free(ip);
    interp_zorder_free(ip);
    tr_free(ip);
}

void interp_reset(interp *ip)
{
    interp_default_state(&ip->st);
    interp_textures_free(ip);
    interp_eval_free(ip);
    interp_nurbs_free(ip);
    ip->in_begin = false;
    ip->prim_plain = 0;
    ip->camera_fixed = false;
    ip->frame_begin = false;
    ip->frame_name[0] = '\0';
    interp_lists_reset(ip);
    interp_arrays_forget(ip);
}

void interp_copy_state(interp *dst, const interp *src)
{
    /* The plain part by value; the heap parts stay dst's, filled below. */
    struct interp_textures *tex = dst->st.tex;
    struct interp_eval *eval = dst->st.eval;
    struct interp_nurbs *nurbs = dst->st.nurbs;
    struct interp_lists *lists = dst->st.lists;
    dst->st = src->st;
    dst->st.tex = tex;
    dst->st.eval = eval;
    dst->st.nurbs = nurbs;
    dst->st.lists = lists;
    if (interp_textures_copy(dst, src) != 0 && dst->scene)
        dst->scene->failed = true;
    if (!interp_lists_copy(dst, src) && dst->scene)
        dst->scene->failed = true;
    if (interp_eval_copy(dst, src) != 0 && dst->scene)
        dst->scene->failed = true;
    if (interp_nurbs_copy(dst, src) != 0 && dst->scene)
        dst->scene->failed = true;
}

void interp_set_resources(interp *ip, interp_resource_fn fn, void *ctx)
{
    ip->res_fn = fn;
    ip->res_ctx = ctx;
}

void interp_attach(interp *ip, scene *out, diag_log *log)
{
    ip->scene = out;
    ip->log = log;
}

void interp_set_frame(interp *ip, uint64_t frame_index, const char *label)
{
    ip->frame_index = frame_index;
    snprintf(ip->label, sizeof ip->label, "%s", label ? label : "");
}

const gl_state *interp_state(const interp *ip) { return &ip->st; }

const mat4 *interp_matrix(const interp *ip, int mode)
{
    switch (mode) {
    case INTERP_PROJ:
        return &ip->st.projection[ip->st.depth[INTERP_PROJ]];
    case INTERP_TEX:
        return &ip->st.texture[ip->st.depth[INTERP_TEX]];
    default:
        return &ip->st.modelview[ip->st.depth[INTERP_MV]];
    }
}


const char *interp_frame_name(const interp *ip) { return ip->frame_begin ? ip->frame_name : NULL; }

/* ---- Running commands -------------------------------------------------------------- */

void interp_exec(interp *ip, const rgl_cmd *cmd)
{
    if (cmd->opcode >= DISPATCH_SIZE || !dispatch[cmd->opcode])
        return; /* the decoder only yields table rows; keep hostile input harmless */
    ip->cmd = cmd;
    if (ip->in_begin && !ip->begin_ok[cmd->opcode]) {
        interp_bad_op(ip, "not allowed between glBegin and glEnd");
        return;
    }
    dispatch[cmd->opcode](ip, cmd);
}

/* The per-vertex commands with a fixed encoding (a one-byte opcode, then
 * little-endian floats or bytes: docs/format.md) are decoded here directly,
 * without the general decoder, when they cannot fail: they are most of a
 * trace. Everything else, and every case that needs a diagnostic, goes
 * through rgl_cmd_next and interp_exec. The result is the same either way
 * (tests/translate/test_interp.c checks it). */
static inline float wire_f32(const uint8_t *p) { return rgl_bits_f32(rgl_get_u32(p)); }

/* The current normal and colour, stored from values in registers: their
 * readers take them as values too (interp_add_vertex_nc), or as single
 * floats. Built in a local and copied, they were read back from the
 * stack in wider loads than they were stored with, a store-forwarding
 * stall at every call. */
static inline void set_normal(gl_attribs *a, float n0, float n1, float n2)
{
    a->current.normal[0] = n0;
    a->current.normal[1] = n1;
    a->current.normal[2] = n2;
}

static inline void put4(float *d, float c0, float c1, float c2, float c3)
{
    d[0] = c0;
    d[1] = c1;
    d[2] = c2;
    d[3] = c3;
}

static inline void set_colour(interp *ip, float c0, float c1, float c2, float c3)
{
    gl_attribs *a = &ip->st.a;
    put4(a->current.color, c0, c1, c2, c3);
    if (!a->caps[INTERP_CAP_COLOR_MATERIAL])
        return;
    if (ip->st.cm.stale) {
        interp_cm_colour(ip);
        return;
    }
    if (a->lighting.color_material_face == GL_FRONT_AND_BACK &&
        a->lighting.color_material_mode == GL_AMBIENT_AND_DIFFUSE) {
        /* GL's default, interp_color_material_update's first case */
        for (int f = 0; f < 2; f++) {
            put4(a->lighting.material[f].ambient, c0, c1, c2, c3);
            put4(a->lighting.material[f].diffuse, c0, c1, c2, c3);
        }
    } else {
        interp_color_material_update(ip);
    }
}

static size_t fast_command(interp *ip, const uint8_t *p, size_t left)
{
    gl_attribs *a = &ip->st.a;
    switch (p[0]) {
    case RGL_OP_Vertex3f:
        if (left < 13 || !ip->in_begin || ip->prim_skip)
            return 0;
        interp_add_vertex(ip, wire_f32(p + 1), wire_f32(p + 5), wire_f32(p + 9), 1);
        return 13;
    case RGL_OP_Vertex2f:
        if (left < 9 || !ip->in_begin || ip->prim_skip)
            return 0;
        interp_add_vertex(ip, wire_f32(p + 1), wire_f32(p + 5), 0, 1);
        return 9;
    case RGL_OP_Normal3f:
        if (left < 13)
            return 0;
        set_normal(a, wire_f32(p + 1), wire_f32(p + 5), wire_f32(p + 9));
        return 13;
    case RGL_OP_TexCoord2f:
        if (left < 9)
            return 0;
        a->current.texcoord[0] = wire_f32(p + 1);
        a->current.texcoord[1] = wire_f32(p + 5);
        a->current.texcoord[2] = 0;
        a->current.texcoord[3] = 1;
        return 9;
    case RGL_OP_Color3f:
    case RGL_OP_Color4f: {
        size_t n = p[0] == RGL_OP_Color3f ? 3 : 4;
        if (left < 1 + 4 * n)
            return 0;
        set_colour(ip, wire_f32(p + 1), wire_f32(p + 5), wire_f32(p + 9),
                   n == 4 ? wire_f32(p + 13) : 1);
        return 1 + 4 * n;
    }
    case RGL_OP_Color3ub:
    case RGL_OP_Color4ub: {
        size_t n = p[0] == RGL_OP_Color3ub ? 3 : 4;
        if (left < 1 + n)
            return 0;
        set_colour(ip, (float)(p[1] / 255.0), (float)(p[2] / 255.0), (float)(p[3] / 255.0),
                   n == 4 ? (float)(p[4] / 255.0) : 1);
        return 1 + n;
    }
    default:
        return 0;
    }
}

/* Whether three interp_budget_count calls in a row pass when nothing
 * between them cuts the run: none is at a heavy check (every 1024th
 * command) and the command count stays within its limit. */
static inline bool budget_count3(const interp *ip)
{
    uint64_t r = ip->cmds_run & 1023;
    return !ip->cut && ip->cmds_run + 3 <= INTERP_LIMIT(ip, COMMANDS) &&
           ((r != 0 && r <= 1021) || ip->heavy || !ip->heavy_fn);
}

rgl_status interp_run(interp *ip, const uint8_t *data, size_t size, uint64_t base_offset,
                      rgl_error *err)
{
    rgl_cmd_iter it;
    rgl_cmd cmd;
    rgl_status st = RGL_END;

    /* The scene's counts passed the budget after the last command, and
     * the commands since changed none it checks: then after a call of
     * fast_command only the command count needs checking. Of those calls
     * only glVertex adds to a count, nverts, which interp_add_vertex keeps
     * within its limit (interp_budget_vertex). */
    bool counts_ok = false;
    rgl_cmd_iter_init(&it, data, size, base_offset);
    while (!ip->cut) {
        /* A run of such calls, with the iterator in locals. */
        const uint8_t *p = it.pos, *end = it.end;
        uint64_t k = 0;
        size_t n;
        bool ok = true;
        while (p < end) {
            const uint8_t *at = p;
            if (counts_ok && end - p >= 39 && p[0] == RGL_OP_Normal3f &&
                p[13] == RGL_OP_Color3f && p[26] == RGL_OP_Vertex3f && ip->in_begin &&
                !ip->prim_skip && ip->prim_plain) {
                /* glNormal3f, glColor3f, glVertex3f of a plain primitive:
                 * the vertex takes the normal and colour from here. Each
                 * call is still counted and checked in turn. */
                float n0 = wire_f32(p + 1), n1 = wire_f32(p + 5), n2 = wire_f32(p + 9);
                float c0 = wire_f32(p + 14), c1 = wire_f32(p + 18), c2 = wire_f32(p + 22);
                set_normal(&ip->st.a, n0, n1, n2);
                if (budget_count3(ip)) {
                    /* The three checks at once: only the vertex can cut. */
                    set_colour(ip, c0, c1, c2, 1);
                    ip->cmds_run += 2;
                    at = p + 26;
                    interp_add_vertex_nc(ip, wire_f32(p + 27), wire_f32(p + 31), wire_f32(p + 35),
                                         n0, n1, n2, c0, c1, c2, 1);
                    p += 39;
                    k += 3;
                    if (!ip->cut) {
                        ip->cmds_run++;
                        continue;
                    }
                    ok = !interp_budget_over(ip, base_offset + (uint64_t)(at - data));
                    break;
                }
                p += 13;
                k++;
                if (interp_budget_count(ip)) {
                    at = p;
                    set_colour(ip, c0, c1, c2, 1);
                    p += 13;
                    k++;
                    if (interp_budget_count(ip)) {
                        at = p;
                        interp_add_vertex_nc(ip, wire_f32(p + 1), wire_f32(p + 5), wire_f32(p + 9),
                                             n0, n1, n2, c0, c1, c2, 1);
                        p += 13;
                        k++;
                        if (interp_budget_count(ip))
                            continue;
                    }
                }
                ok = !interp_budget_over(ip, base_offset + (uint64_t)(at - data));
                break;
            }
            if ((n = fast_command(ip, p, (size_t)(end - p))) == 0)
                break;
            p += n;
            k++;
            if (counts_ok && interp_budget_count(ip))
                continue;
            uint64_t offset = base_offset + (uint64_t)(at - data);
            ok = counts_ok ? !interp_budget_over(ip, offset)
                           : (counts_ok = interp_budget_after(ip, offset));
            if (!ok)
                break;
        }
        it.pos = p;
        it.index += k;
        if (!ok)
            break;
        if ((st = rgl_cmd_next(&it, &cmd)) != RGL_OK)
            break;
        interp_exec(ip, &cmd);
        if (!(counts_ok = interp_budget_after(ip, cmd.offset)))
            break;
    }
    if (ip->cut)
        st = RGL_END; /* cut, not damaged: what ran is kept */
    ip->cmd = NULL;
    interp_arrays_forget(ip);
    if (st == RGL_END)
        return RGL_OK;
    if (err)
        *err = it.error;
    return st;
}

rgl_status interp_run_slow(interp *ip, const uint8_t *data, size_t size, uint64_t base_offset,
                           rgl_error *err)
{
    rgl_cmd_iter it;
    rgl_cmd cmd;
    rgl_status st = RGL_END;

    rgl_cmd_iter_init(&it, data, size, base_offset);
    while (!ip->cut && (st = rgl_cmd_next(&it, &cmd)) == RGL_OK) {
        interp_exec(ip, &cmd);
        if (!interp_budget_after(ip, cmd.offset)) {
            st = RGL_END;
            break;
        }
    }
    ip->cmd = NULL;
    interp_arrays_forget(ip);
    if (st == RGL_END)
        return RGL_OK;
    if (err)
        *err = it.error;
    return st;
}

/* ---- Diagnostics ---------------------------------------------------------------- */

static void make_prefix_at(const interp *ip, char *out, size_t cap, bool has_cmd, uint64_t index,
                           const char *name, uint64_t offset)
{
    int n = snprintf(out, cap, "frame %llu", (unsigned long long)ip->frame_index);
    if (n < 0 || (size_t)n >= cap)
        return;
    if (ip->label[0]) {
        int k = snprintf(out + n, cap - (size_t)n, ", %s", ip->label);
        if (k < 0 || (size_t)(n + k) >= cap)
            return;
        n += k;
    }
    if (has_cmd)
        snprintf(out + n, cap - (size_t)n, ", cmd %llu (%s) @0x%llx", (unsigned long long)index,
                 name ? name : "?", (unsigned long long)offset);
}

static void make_prefix(const interp *ip, char *out, size_t cap)
{
    const rgl_cmd *c = ip->cmd;
    make_prefix_at(ip, out, cap, c != NULL, c ? c->index : 0, c && c->info ? c->info->name : NULL,
                   c ? c->offset : 0);
}

void interp_diag(interp *ip, diag_kind kind, const char *fmt, ...)
{
    if (!ip->log)
        return;
    diag_entry *e = &ip->log->e[kind];
    if (e->kept >= DIAG_KEEP) {
        e->count++; /* nothing more to keep: skip the formatting */
        return;
    }
    char prefix[DIAG_PREFIX], msg[DIAG_TEXT];
    va_list ap;
    make_prefix(ip, prefix, sizeof prefix);
    va_start(ap, fmt);
    int n = vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    if (n < 0 || (size_t)n >= sizeof msg) {
        diag_drop(ip->log, kind); /* never a message cut short */
        return;
    }
    diag_add(ip->log, kind, prefix, "%s", msg);
}

_Static_assert(DIAG_COUNT - DIAG_FIRST_NOTE <= 64 * INTERP_NOTE_WORDS,
               "the notes of a frame are bits of INTERP_NOTE_WORDS uint64_t");

void interp_clear_notes(interp *ip)
{
    memset(ip->notes_seen, 0, sizeof ip->notes_seen);
    memset(ip->notes_held, 0, sizeof ip->notes_held);
}

void interp_frame_note(interp *ip, diag_kind kind) { interp_note(ip, kind); }

void interp_frame_note_held(interp *ip, diag_kind kind, const char *why)
{
    interp_note_held(ip, kind, why);
}

/* The word of the notes' bitsets that holds kind, and its bit there. */
static size_t note_word(diag_kind kind, uint64_t *bit)
{
    unsigned i = (unsigned)(kind - DIAG_FIRST_NOTE);
    *bit = 1ull << (i % 64);
    return i / 64;
}

bool interp_note_said(const interp *ip, diag_kind kind)
{
    uint64_t bit;
    size_t w = note_word(kind, &bit);
    return !ip->log || (ip->notes_seen[w] & bit);
}

void interp_note(interp *ip, diag_kind kind)
{
    uint64_t bit;
    size_t w = note_word(kind, &bit);
    if (!ip->log || (ip->notes_seen[w] & bit))
        return;
    ip->notes_seen[w] |= bit;
    char prefix[DIAG_PREFIX];
    make_prefix(ip, prefix, sizeof prefix);
    diag_add(ip->log, kind, prefix, "%s", diag_kind_name(kind));
}

void interp_note_cmd(interp *ip, diag_kind kind, bool has_cmd, uint64_t index, const char *name,
                     uint64_t offset, const char *why)
{
    uint64_t bit;
    size_t w = note_word(kind, &bit);
    if (!ip->log || (ip->notes_seen[w] & bit) || (why && (ip->notes_held[w] & bit)))
        return;
    char prefix[DIAG_PREFIX];
    make_prefix_at(ip, prefix, sizeof prefix, has_cmd, index, name, offset);
    if (why) {
        ip->notes_held[w] |= bit;
        diag_add_held(ip->log, kind, prefix, why);
    } else {
        ip->notes_seen[w] |= bit;
        diag_add(ip->log, kind, prefix, "%s", diag_kind_name(kind));
    }
}

void interp_note_held(interp *ip, diag_kind kind, const char *why)
{
    uint64_t bit;
    size_t w = note_word(kind, &bit);
    if (!ip->log || ((ip->notes_seen[w] | ip->notes_held[w]) & bit))
        return;
    ip->notes_held[w] |= bit;
    char prefix[DIAG_PREFIX];
    make_prefix(ip, prefix, sizeof prefix);
    diag_add_held(ip->log, kind, prefix, why);
}

void interp_note_pov(interp *ip, diag_kind kind, diag_kind gltf)
{
    if (!ip->not_pov) {
        interp_note(ip, kind);
        return;
    }
    interp_note_held(ip, kind, "written as glTF, not for POV-Ray");
    if (gltf != DIAG_COUNT)
        interp_note(ip, gltf);
}

void interp_bad_enum(interp *ip, const char *what, uint32_t value)
{
    interp_diag(ip, DIAG_GL_INVALID_ENUM, "invalid %s 0x%x", what, value);
}

void interp_bad_value(interp *ip, const char *detail)
{
    interp_diag(ip, DIAG_GL_INVALID_VALUE, "invalid value: %s", detail);
}

void interp_bad_op(interp *ip, const char *why)
{
    interp_diag(ip, DIAG_GL_INVALID_OPERATION, "invalid operation: %s", why);
}

bool interp_reject_in_begin(interp *ip)
{
    if (!ip->in_begin)
        return false;
    interp_bad_op(ip, "not allowed between glBegin and glEnd");
    return true;
}

/* ---- glEnable / glDisable ---------------------------------------------------------- */

static void set_cap(interp *ip, const rgl_cmd *cmd, bool on)
{
    GLenum cap = arg_enum(cmd, 0);
    int i = interp_cap_index(cap);
    /* Mesa's compatibility context takes the client arrays here, as
     * glEnableClientState (checked with OSMesa); the recorder records them
     * as that, and the draws' @ArrayData carry what they enable. */
    if (i < 0 && (cap == GL_VERTEX_ARRAY || cap == GL_NORMAL_ARRAY || cap == GL_COLOR_ARRAY ||
                  cap == GL_INDEX_ARRAY || cap == GL_TEXTURE_COORD_ARRAY ||
                  cap == GL_EDGE_FLAG_ARRAY || cap == GL_FOG_COORD_ARRAY ||
                  cap == GL_SECONDARY_COLOR_ARRAY))
        return;
    if (i < 0) {
        interp_bad_enum(ip, "capability", cap);
        return;
    }
    bool was = ip->st.a.caps[i];
    ip->st.a.caps[i] = on;
    /* GL 1.x 2.13.3: while COLOR_MATERIAL is on, the material tracks the
     * current colour, starting at the glEnable (as Mesa does it:
     * interp_cm_enable). */
    if (i == INTERP_CAP_COLOR_MATERIAL && on != was)
        interp_cm_enable(ip, on);
}

void interp_enable(interp *ip, const rgl_cmd *cmd) { set_cap(ip, cmd, true); }
void interp_disable(interp *ip, const rgl_cmd *cmd) { set_cap(ip, cmd, false); }

/* ---- glPushAttrib / glPopAttrib ----------------------------------------------------- */

void interp_pushattrib(interp *ip, const rgl_cmd *cmd)
{
    gl_state *st = &ip->st;
    if (st->attrib_depth >= INTERP_ATTRIB_DEPTH) {
        interp_diag(ip, DIAG_GL_STACK_OVERFLOW, "attribute stack overflow (depth %d)",
                    INTERP_ATTRIB_DEPTH);
        return;
    }
    interp_cm_flush(ip);
    gl_attrib_entry *e = &st->attrib_stack[st->attrib_depth++];
    e->mask = (uint32_t)cmd->arg[0].v.u;
    e->saved = st->a;
}

void interp_popattrib(interp *ip, const rgl_cmd *cmd)
{
    (void)cmd;
    gl_state *st = &ip->st;
    if (st->attrib_depth <= 0) {
        interp_diag(ip, DIAG_GL_STACK_UNDERFLOW, "attribute stack underflow");
        return;
    }
    interp_cm_flush(ip);
    const gl_attrib_entry *e = &st->attrib_stack[--st->attrib_depth];
    const gl_attribs *s = &e->saved;
    gl_attribs *a = &st->a;
    uint32_t m = e->mask;

    if (m & GL_CURRENT_BIT)
        a->current = s->current;
    if (m & GL_LIGHTING_BIT)
        a->lighting = s->lighting;
    if (m & GL_POLYGON_BIT) { /* the stipple mask is GL_POLYGON_STIPPLE_BIT's alone */
        uint8_t mask[sizeof a->polygon.stipple];
        memcpy(mask, a->polygon.stipple, sizeof mask);
        a->polygon = s->polygon;
        memcpy(a->polygon.stipple, mask, sizeof mask);
    }
    if (m & GL_POLYGON_STIPPLE_BIT)
        memcpy(a->polygon.stipple, s->polygon.stipple, sizeof a->polygon.stipple);
    if (m & GL_LINE_BIT)
        a->line = s->line;
    if (m & GL_POINT_BIT)
        a->point = s->point;
    if (m & GL_VIEWPORT_BIT)
        a->viewport = s->viewport;
    if (m & GL_TRANSFORM_BIT)
        a->transform = s->transform;
    if (m & GL_COLOR_BUFFER_BIT)
        a->color_buffer = s->color_buffer;
    if (m & GL_DEPTH_BUFFER_BIT)
        a->depth = s->depth;
    if (m & GL_ACCUM_BUFFER_BIT)
        a->accum = s->accum;
    if (m & GL_FOG_BIT)
        a->fog = s->fog;
    if (m & GL_HINT_BIT)
        a->hint = s->hint;
    if (m & GL_TEXTURE_BIT)
        a->texture = s->texture;
    if (m & GL_EVAL_BIT)
        a->eval = s->eval;
    if (m & GL_PIXEL_MODE_BIT)
        a->pixel = s->pixel;
    if (m & GL_SCISSOR_BIT)
        a->scissor = s->scissor;
    bool cm_was = a->caps[INTERP_CAP_COLOR_MATERIAL];
    for (int i = 0; i < INTERP_CAP_COUNT; i++)
        if ((m & GL_ENABLE_BIT) || (m & cap_groups[i]))
            a->caps[i] = s->caps[i];
    /* Mesa copies the current colour into the tracked terms when the pop
     * turns colour material on or restores the colour or material under
     * it (measured: tests/programs/cmat_*.c). */
    if (!a->caps[INTERP_CAP_COLOR_MATERIAL]) {
        ip->st.cm.stale = false;
    } else if (!cm_was || (m & (GL_CURRENT_BIT | GL_LIGHTING_BIT))) {
        ip->st.cm.stale = false;
        interp_color_material_update(ip);
    }
}

/* ---- Calls with no effect on the picture ------------------------------------------------- */

void interp_flush(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }
void interp_finish(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }

void interp_hint(interp *ip, const rgl_cmd *cmd)
{
    GLenum target = arg_enum(cmd, 0), mode = arg_enum(cmd, 1);
    GLenum *slot;
    switch (target) {
    case GL_PERSPECTIVE_CORRECTION_HINT: slot = &ip->st.a.hint.perspective; break;
    case GL_POINT_SMOOTH_HINT: slot = &ip->st.a.hint.point; break;
    case GL_LINE_SMOOTH_HINT: slot = &ip->st.a.hint.line; break;
    case GL_POLYGON_SMOOTH_HINT: slot = &ip->st.a.hint.polygon; break;
    case GL_FOG_HINT: slot = &ip->st.a.hint.fog; break;
    default:
        return; /* hints GL 1.x does not name (extensions): accepted, no effect */
    }
    if (mode != GL_FASTEST && mode != GL_NICEST && mode != GL_DONT_CARE) {
        interp_bad_enum(ip, "hint mode", mode);
        return;
    }
    *slot = mode;
}
