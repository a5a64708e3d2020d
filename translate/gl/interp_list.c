/* interp_list.c: display lists.
 *
 * The recorder writes a list's body once, as a COMMANDS resource, and
 * glNewList(list, mode, body=#id) where the list ends (docs/format.md); the
 * frame-start snapshot re-creates the lists known then the same way. Here a
 * list name maps to its body, and glCallList runs the body through the
 * interpreter at the call, with the state of the moment, as GL executes a
 * list (GL 1.x 5.4): state set inside a list stays set after it, and a list
 * that uses the current colour draws in the caller's colour. Lists nest up
 * to GL_MAX_LIST_NESTING (64); deeper calls are skipped, as GL does.
 *
 * Shared output. A list drawn many times would repeat its geometry in the
 * SDL at every call. So each outermost call (not inside glBegin, not inside
 * another list) is compared with the earlier calls of the same body in the
 * frame: when it drew the same meshes (the same vertices with the same
 * colours, normals and texture coordinates, the same triangles and looks,
 * and the same transforms relative to the call's own modelview), those
 * meshes become a prototype (a #declare in SDL) and every such call an
 * instance placing it with its modelview. The rule is on the output, so
 * whatever the list inherits (current colour, material, shade model,
 * culling, which triangles face the camera) keys the prototype by itself: a
 * call whose inherited state changes what it draws gets its own prototype,
 * and one whose output cannot be shared (a list that loads an absolute
 * matrix, draws without a depth test, is fogged or scissored, or is drawn
 * in eye space) stays inline. Lines and points, which are built in eye space, always stay
 * inline.
 */
#include "interp_internal.h"

#include <stdio.h>
#include <string.h>

#include "namemap.h"
#include "talloc.h"

typedef struct list_entry {
    uint32_t name;
    uint32_t body;  /* resource id; 0: an empty list */
    bool fetched;   /* data/size/offset hold the body */
    const uint8_t *data;
    size_t size;
    uint64_t offset;
} list_entry;

struct interp_lists {
    list_entry *v; /* unordered */
    size_t n, cap;
    namemap names; /* name -> index in v */
};

/* One outermost call's meshes, kept while the frame lasts for later calls
 * of the same body to match. */
typedef struct list_group {
    uint32_t body;
    uint32_t generation; /* of the scene: a glClear forgets the group */
    size_t m0, nm, v0, nv, t0, nt;
    uint32_t proto;   /* 0: not yet shared; k: scene.protos[k - 1] */
    mat4 first_call;  /* the first call's placement */
    size_t rel;       /* index in mats of the first mesh's relative transform */
} list_group;

struct interp_groups {
    list_group *v;
    size_t n, cap;
    mat4 *mats;
    size_t nmats, cap_mats;
};

/* List calls per frame: a list that calls itself twice would otherwise
 * run 2^64 bodies (GL would hang too); a hostile trace must not hang the
 * translator. */
#define LIST_CALLS_PER_FRAME (1u << 20)

/* Distinct outputs kept per body: a list whose every call differs (a
 * painter's shift, an absolute matrix) stops being compared after these. */
#define GROUPS_PER_BODY 8

/* ---- The table ------------------------------------------------------------------- */

static list_entry *list_find(interp *ip, uint32_t name)
{
    struct interp_lists *t = ip->st.lists;
    if (!t)
        return NULL;
    int64_t i = namemap_get(&t->names, name);
    return i >= 0 ? &t->v[i] : NULL;
}

static bool list_define(interp *ip, uint32_t name, uint32_t body)
{
    if (!ip->st.lists) {
        ip->st.lists = tr_realloc(NULL, sizeof *ip->st.lists);
        if (!ip->st.lists)
            return false;
        memset(ip->st.lists, 0, sizeof *ip->st.lists);
    }
    struct interp_lists *t = ip->st.lists;
    int64_t found = namemap_get(&t->names, name);
    size_t i = found >= 0 ? (size_t)found : t->n;
    if (found < 0) {
        if (t->n >= UINT32_MAX || tr_grow((void **)&t->v, &t->cap, t->n + 1, sizeof *t->v) != 0 ||
            namemap_put(&t->names, name, (uint32_t)t->n) != 0)
            return false;
        t->n++;
    }
    memset(&t->v[i], 0, sizeof t->v[i]);
    t->v[i].name = name;
    t->v[i].body = body;
    return true;
}

void interp_lists_reset(interp *ip)
{
    if (ip->st.lists) {
        ip->st.lists->n = 0;
        namemap_clear(&ip->st.lists->names);
    }
    ip->list_depth = 0;
}

bool interp_lists_copy(interp *dst, const interp *src)
{
    interp_lists_reset(dst);
    if (!src->st.lists || src->st.lists->n == 0)
        return true;
    if (!dst->st.lists) {
        dst->st.lists = tr_realloc(NULL, sizeof *dst->st.lists);
        if (!dst->st.lists)
            return false;
        memset(dst->st.lists, 0, sizeof *dst->st.lists);
    }
    struct interp_lists *t = dst->st.lists;
    if (tr_grow((void **)&t->v, &t->cap, src->st.lists->n, sizeof *t->v) != 0 ||
        namemap_copy(&t->names, &src->st.lists->names) != 0)
        return false;
    memcpy(t->v, src->st.lists->v, src->st.lists->n * sizeof *t->v);
    t->n = src->st.lists->n;
    return true;
}

void interp_lists_free(interp *ip)
{
    if (ip->st.lists) {
        tr_free(ip->st.lists->v);
        namemap_finish(&ip->st.lists->names);
    }
    tr_free(ip->st.lists);
    ip->st.lists = NULL;
    if (ip->groups) {
        tr_free(ip->groups->v);
        tr_free(ip->groups->mats);
    }
    tr_free(ip->groups);
    ip->groups = NULL;
}

void interp_lists_begin_frame(interp *ip)
{
    if (ip->groups)
        ip->groups->n = ip->groups->nmats = 0;
    ip->list_depth = 0;
    ip->list_calls = 0;
}

/* The body of e, fetched once. False (after a diagnostic) when unreadable. */
static bool list_fetch(interp *ip, list_entry *e)
{
    if (e->fetched)
        return true;
    if (e->body == 0) { /* recorded without a body: an empty list */
        e->fetched = true;
        e->data = NULL;
        e->size = 0;
        return true;
    }
    if (!ip->res_fn) {
        interp_diag(ip, DIAG_IGNORED, "display list %u: no trace to read body #%u from",
                    e->name, e->body);
        return false;
    }
    rgl_resource res;
    rgl_error err;
    memset(&err, 0, sizeof err);
    char what[DIAG_TEXT];
    if (ip->res_fn(ip->res_ctx, e->body, &res, &err) != RGL_OK) {
        interp_diag(ip, DIAG_IGNORED, "display list %u: body #%u unreadable (%s): call skipped",
                    e->name, e->body, rgl_status_str(err.status));
        snprintf(what, sizeof what, "display list %u (body #%u unreadable: %s)", e->name,
                 e->body, rgl_status_str(err.status));
        interp_missing(ip, what);
        return false;
    }
    if (res.kind != RGL_RES_COMMANDS) {
        interp_diag(ip, DIAG_IGNORED,
                    "display list %u: body #%u is not a command sequence: call skipped",
                    e->name, e->body);
        snprintf(what, sizeof what, "display list %u (body #%u is not a command sequence)",
                 e->name, e->body);
        interp_missing(ip, what);
        return false;
    }
    e->fetched = true;
    e->data = res.data;
    e->size = res.size;
    e->offset = res.data_offset;
    return true;
}

/* ---- Shared output ------------------------------------------------------------------ */

static bool mat_close(const mat4 *a, const mat4 *b)
{
    for (int i = 0; i < 16; i++) {
        double x = a->m[i], y = b->m[i];
        if (!(fabs(x - y) <= 1e-9 * (1 + fabs(x) + fabs(y))))
            return false;
    }
    return true;
}

/* Whether the meshes [m0, m0 + nm) drawn by this call (relative transforms
 * rel) are those of group g. */
static bool group_matches(const interp *ip, const list_group *g, size_t m0, size_t v0,
                          size_t t0, const mat4 *rel)
{
    const scene *s = ip->scene;
    const mat4 *grel = ip->groups->mats + g->rel;
    for (size_t k = 0; k < g->nm; k++) {
        const scene_mesh *a = &s->meshes[g->m0 + k], *b = &s->meshes[m0 + k];
        if (a->tri_count != b->tri_count || !scene_look_equal(&a->look, &b->look) ||
            !mat_close(&grel[k], &rel[k]))
            return false;
    }
    /* indexed, not s->tris + t0: the arrays are NULL while the scene has no
     * triangles or vertices, and NULL + 0 is undefined */
    uint32_t ba = (uint32_t)g->v0, bb = (uint32_t)v0;
    for (size_t i = 0; i < g->nt; i++) {
        const scene_tri *ta = &s->tris[g->t0 + i], *tb = &s->tris[t0 + i];
        if (ta->v[0] - ba != tb->v[0] - bb || ta->v[1] - ba != tb->v[1] - bb ||
            ta->v[2] - ba != tb->v[2] - bb || ta->provoking - ba != tb->provoking - bb)
            return false;
    }
    return g->nv == 0 ||
           memcmp(&s->verts[g->v0], &s->verts[v0], g->nv * sizeof *s->verts) == 0;
}

/* Turns group g's meshes into a prototype placed by the group's first call. */
static bool group_promote(interp *ip, list_group *g)
{
    scene *s = ip->scene;
    scene_proto *p = scene_add_proto(s);
    scene_instance *in = p ? scene_add_instance(s) : NULL;
    if (!in)
        return false;
    p->first_mesh = g->m0;
    p->nmeshes = g->nm;
    g->proto = (uint32_t)s->nprotos;
    for (size_t k = 0; k < g->nm; k++) {
        s->meshes[g->m0 + k].to_eye = ip->groups->mats[g->rel + k];
        s->meshes[g->m0 + k].proto = g->proto;
    }
    in->proto = g->proto - 1;
    in->to_eye = g->first_call;
    return true;
}

typedef struct call_mark {
    size_t m0, v0, t0;
    uint64_t facets; /* ip->shape_facets at the call */
    uint32_t generation;
    uint32_t painter; /* ip->painter at the call */
    bool painter_on;  /* the call began without a depth test */
    mat4 mv, proj;
    int32_t vp[4];
} call_mark;

/* After an outermost call of body `body`: shares its meshes with an earlier
 * call's when they are the same, or keeps them for later calls to match. */
static void share_output(interp *ip, uint32_t body, const call_mark *mk)
{
    scene *s = ip->scene;
    s->mesh_floor = s->nmeshes; /* later draws start meshes of their own */
    if (s->failed || s->generation != mk->generation || s->nmeshes <= mk->m0 ||
        s->nverts < mk->v0 || s->ntris < mk->t0 || !ip->camera_fixed)
        return;
    size_t nm = s->nmeshes - mk->m0, nv = s->nverts - mk->v0, nt = s->ntris - mk->t0;
    if (s->meshes[mk->m0].first_tri != mk->t0)
        return;
    for (size_t k = 0; k < nm; k++) {
        const scene_mesh *m = &s->meshes[mk->m0 + k];
        if (m->in_eye || m->proto)
            return;
    }
    for (size_t i = 0; i < nt; i++) {
        const scene_tri *t = &s->tris[mk->t0 + i];
        for (int k = 0; k < 3; k++)
            if (t->v[k] < mk->v0 || t->v[k] >= s->nverts)
                return;
        if (t->provoking < mk->v0 || t->provoking >= s->nverts)
            return;
    }
    /* A scissor box lies in the picture, not in the list's space; so do
     * user clip planes and the stencil region, in eye space, and fog, a
     * function of the eye distance that differs per call. */
    for (size_t k = 0; k < nm; k++) {
        const scene_look *lk = &s->meshes[mk->m0 + k].look;
        if (lk->scissored || lk->clip || lk->stencil_n || lk->fog || lk->pstipple)
            return;
    }
    mat4 call, inv;
    if (!interp_object_to_eye(ip, &mk->mv, &mk->proj, mk->vp, &call) || !mat4_affine(&call) ||
        !mat4_invert(&call, &inv))
        return;
    /* Drawn without a depth test, the first draw of the call moved toward
     * the camera by its painter's shift: the call's placement carries it,
     * so a call of one draw is shared; later draws of a call are each
     * shifted a little more, toward a camera that lies elsewhere from each
     * call, and such calls do not match (they stay inline). */
    if (mk->painter_on)
        interp_painter_apply(ip, mk->painter < INTERP_PAINTER_MAX ? mk->painter + 1 : mk->painter,
                             &call);
    if (!mat4_invert(&call, &inv))
        return;

    if (!ip->groups) {
        ip->groups = tr_realloc(NULL, sizeof *ip->groups);
        if (!ip->groups) {
            s->failed = true;
            return;
        }
        memset(ip->groups, 0, sizeof *ip->groups);
    }
    struct interp_groups *gs = ip->groups;
    if (tr_grow((void **)&gs->mats, &gs->cap_mats, gs->nmats + nm, sizeof *gs->mats) != 0) {
        s->failed = true;
        return;
    }
    mat4 *rel = gs->mats + gs->nmats; /* scratch until kept */
    for (size_t k = 0; k < nm; k++) {
        rel[k] = mat4_mul(&inv, &s->meshes[mk->m0 + k].to_eye);
        if (!mat4_finite(&rel[k]))
            return;
    }

    size_t same_body = 0;
    for (size_t i = 0; i < gs->n; i++) {
        list_group *g = &gs->v[i];
        if (g->body != body || g->generation != s->generation)
            continue;
        same_body++;
        if (g->nm != nm || g->nv != nv || g->nt != nt ||
            !group_matches(ip, g, mk->m0, mk->v0, mk->t0, rel))
            continue;
        if (!g->proto && !group_promote(ip, g))
            return;
        scene_instance *in = scene_add_instance(s);
        if (!in)
            return;
        in->proto = g->proto - 1;
        in->to_eye = call;
        s->nmeshes = mk->m0;
        s->nverts = mk->v0;
        s->ntris = mk->t0;
        /* Its tessellated shapes are the prototype's: the frame's cap on
         * facets (interp_shape.c) counts them once, as the scene holds
         * them. */
        ip->shape_facets = mk->facets;
        s->mesh_floor = s->nmeshes;
        return;
    }
    if (same_body >= GROUPS_PER_BODY)
        return;
    if (tr_grow((void **)&gs->v, &gs->cap, gs->n + 1, sizeof *gs->v) != 0) {
        s->failed = true;
        return;
    }
    list_group *g = &gs->v[gs->n++];
    memset(g, 0, sizeof *g);
    g->body = body;
    g->generation = s->generation;
    g->m0 = mk->m0;
    g->nm = nm;
    g->v0 = mk->v0;
    g->nv = nv;
    g->t0 = mk->t0;
    g->nt = nt;
    g->first_call = call;
    g->rel = gs->nmats;
    gs->nmats += nm;
}

/* ---- Calls ---------------------------------------------------------------------------- */

static void call_list(interp *ip, uint32_t name)
{
    if (ip->cut)
        return;
    if (ip->list_depth >= INTERP_MAX_LIST_NESTING) {
        interp_diag(ip, DIAG_LIMIT, "display list %u nested deeper than %d: call skipped", name,
                    INTERP_MAX_LIST_NESTING);
        return;
    }
    if (ip->list_calls >= LIST_CALLS_PER_FRAME) {
        if (ip->list_calls++ == LIST_CALLS_PER_FRAME)
            interp_diag(ip, DIAG_LIMIT, "more than %u display-list calls in one frame: the rest "
                        "skipped", LIST_CALLS_PER_FRAME);
        return;
    }
    ip->list_calls++;
    list_entry *e = list_find(ip, name);
    if (!e || !list_fetch(ip, e))
        return; /* GL: calling an undefined list does nothing */
    if (e->size == 0)
        return;
    const uint8_t *data = e->data;
    size_t size = e->size;
    uint64_t offset = e->offset;
    uint32_t body = e->body; /* e may move: the body may define lists */

    scene *s = ip->scene;
    bool share = s && ip->list_depth == 0 && !ip->in_begin;
    call_mark mk;
    if (share) {
        mk.m0 = s->nmeshes;
        mk.v0 = s->nverts;
        mk.t0 = s->ntris;
        mk.facets = ip->shape_facets;
        mk.generation = s->generation;
        mk.painter = ip->painter;
        const gl_attribs *a = &ip->st.a;
        mk.painter_on = !(a->caps[INTERP_CAP_DEPTH_TEST] &&
                          (a->depth.func == GL_LESS || a->depth.func == GL_LEQUAL));
        mk.mv = *interp_matrix(ip, INTERP_MV);
        mk.proj = *interp_matrix(ip, INTERP_PROJ);
        memcpy(mk.vp, ip->st.a.viewport.rect, sizeof mk.vp);
        s->mesh_floor = s->nmeshes;
    }
    const rgl_cmd *outer = ip->cmd;
    rgl_error err;
    /* GLU quadric calls are client state, done at compile time and never
     * stored in a list: the recorder writes a compiled shape's quadric
     * state into the body before it, for the body alone. */
    interp_quadric quadrics[INTERP_QUADRICS];
    memcpy(quadrics, ip->st.quadrics, sizeof quadrics);
    ip->list_depth++;
    rgl_status st = interp_run(ip, data, size, offset, &err);
    ip->list_depth--;
    memcpy(ip->st.quadrics, quadrics, sizeof quadrics);
    ip->cmd = outer;
    if (st != RGL_OK) {
        interp_diag(ip, DIAG_IGNORED,
                    "display list %u: body #%u damaged at 0x%llx (%s): the rest of it skipped",
                    name, body, (unsigned long long)err.offset, rgl_status_str(st));
        char what[DIAG_TEXT];
        snprintf(what, sizeof what, "the rest of display list %u (body #%u damaged at 0x%llx: %s)",
                 name, body, (unsigned long long)err.offset, rgl_status_str(st));
        interp_missing(ip, what);
    }
    if (share) {
        interp_budget_peak(ip);
        share_output(ip, body, &mk);
    }
}

void interp_calllist(interp *ip, const rgl_cmd *cmd)
{
    interp_cm_flush(ip);
    call_list(ip, (uint32_t)cmd->arg[0].v.u);
}

/* glCallLists: n names of `type`, each offset by glListBase (GL 1.x 5.4). */
void interp_calllists(interp *ip, const rgl_cmd *cmd)
{
    int64_t n = cmd->arg[0].v.i;
    GLenum type = arg_enum(cmd, 1);
    const rgl_arg *blob = &cmd->arg[2];
    size_t ts;
    switch (type) {
    case GL_BYTE: case GL_UNSIGNED_BYTE: ts = 1; break;
    case GL_SHORT: case GL_UNSIGNED_SHORT: case GL_2_BYTES: ts = 2; break;
    case GL_3_BYTES: ts = 3; break;
    case GL_INT: case GL_UNSIGNED_INT: case GL_FLOAT: case GL_4_BYTES: ts = 4; break;
    default:
        interp_bad_enum(ip, "list name type", type);
        return;
    }
    if (n < 0) {
        interp_bad_value(ip, "glCallLists with a negative count");
        return;
    }
    if ((uint64_t)blob->count != (uint64_t)n * ts) {
        interp_bad_value(ip, "glCallLists names do not match the count and type");
        return;
    }
    const uint8_t *p = blob->bytes;
    interp_cm_flush(ip);
    ip->cmds_run += (uint64_t)n; /* each name costs as a command */
    for (int64_t i = 0; i < n && !ip->cut; i++, p += ts) {
        uint32_t off;
        switch (type) {
        case GL_BYTE: off = (uint32_t)(int32_t)(int8_t)p[0]; break;
        case GL_UNSIGNED_BYTE: off = p[0]; break;
        case GL_SHORT: off = (uint32_t)(int32_t)(int16_t)(uint16_t)(p[0] | p[1] << 8); break;
        case GL_UNSIGNED_SHORT: off = (uint32_t)(p[0] | p[1] << 8); break;
        case GL_2_BYTES: off = (uint32_t)p[0] << 8 | p[1]; break;
        case GL_3_BYTES: off = (uint32_t)p[0] << 16 | (uint32_t)p[1] << 8 | p[2]; break;
        case GL_4_BYTES:
            off = (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 | p[3];
            break;
        case GL_FLOAT: {
            uint32_t bits = (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 |
                            (uint32_t)p[3] << 24;
            float f;
            memcpy(&f, &bits, sizeof f);
            if (!(f >= 0 && f < 4294967296.0f))
                continue; /* no list has such a name */
            off = (uint32_t)f;
            break;
        }
        default: /* GL_INT, GL_UNSIGNED_INT */
            off = (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 |
                  (uint32_t)p[3] << 24;
            break;
        }
        call_list(ip, ip->st.list_base + off);
    }
}

/* ---- Definitions ------------------------------------------------------------------------ */

void interp_genlists(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }
void interp_endlist(interp *ip, const rgl_cmd *cmd)
{
    (void)cmd;
    interp_cm_flush(ip);
}

/* The recorder writes glNewList where the list ends, carrying its body. */
void interp_newlist(interp *ip, const rgl_cmd *cmd)
{
    uint32_t name = (uint32_t)cmd->arg[0].v.u;
    GLenum mode = arg_enum(cmd, 1);
    uint32_t body = (uint32_t)cmd->arg[2].v.u;
    interp_cm_flush(ip);
    if (mode != GL_COMPILE && mode != GL_COMPILE_AND_EXECUTE) {
        interp_bad_enum(ip, "list mode", mode);
        return;
    }
    if (name == 0) {
        interp_bad_value(ip, "glNewList of list 0");
        return;
    }
    if (ip->list_depth > 0) {
        interp_bad_op(ip, "glNewList inside a display list");
        return;
    }
    if (!list_define(ip, name, body)) {
        if (ip->scene)
            ip->scene->failed = true;
        return;
    }
    if (mode == GL_COMPILE_AND_EXECUTE) {
        /* GL runs this body as immediate calls, not as a compiled list
         * (which matters to how quads split: interp_assemble.c). */
        ip->list_ce = true;
        call_list(ip, name);
        ip->list_ce = false;
    }
}

void interp_deletelists(interp *ip, const rgl_cmd *cmd)
{
    uint32_t first = (uint32_t)cmd->arg[0].v.u;
    int64_t range = cmd->arg[1].v.i;
    if (range < 0) {
        interp_bad_value(ip, "glDeleteLists with a negative range");
        return;
    }
    struct interp_lists *t = ip->st.lists;
    if (!t)
        return;
    uint64_t end = (uint64_t)first + (uint64_t)range;
    /* By name or over the table, whichever is shorter; it costs as many
     * commands (a list calling glDeleteLists 10^7 times stays bounded). */
    if ((uint64_t)range < t->n) {
        ip->cmds_run += (uint64_t)range;
        for (uint64_t name = first; name < end && name <= UINT32_MAX; name++) {
            int64_t i = namemap_get(&t->names, (uint32_t)name);
            if (i < 0)
                continue;
            namemap_del(&t->names, (uint32_t)name);
            t->v[i] = t->v[--t->n];
            if ((size_t)i < t->n) /* the last entry moved into i */
                namemap_put(&t->names, t->v[i].name, (uint32_t)i);
        }
        return;
    }
    ip->cmds_run += t->n;
    size_t k = 0;
    namemap_clear(&t->names);
    for (size_t i = 0; i < t->n; i++)
        if (!(t->v[i].name >= first && t->v[i].name < end)) {
            t->v[k] = t->v[i];
            namemap_put(&t->names, t->v[k].name, (uint32_t)k); /* cannot grow: fewer than before */
            k++;
        }
    t->n = k;
}

void interp_listbase(interp *ip, const rgl_cmd *cmd)
{
    ip->st.list_base = (uint32_t)cmd->arg[0].v.u;
}
