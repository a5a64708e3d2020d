/* interp_light.c: lights, light model, materials, colour material, fog.
 *
 * The state is kept exactly as GL keeps it (light positions and spot
 * directions transformed into eye space by the modelview current at the
 * glLight call, GL 1.x 2.13.2), validated as GL validates it. Issue 4 turns
 * it into POV-Ray lights and finishes; until then a lit draw shows each
 * vertex in its material's diffuse colour, and says so once.
 */
#include "interp_internal.h"

#include <string.h>

static uint8_t cm_bits(GLenum mode);

static int face_mask(GLenum face)
{
    switch (face) {
    case GL_FRONT: return 1;
    case GL_BACK: return 2;
    case GL_FRONT_AND_BACK: return 3;
    default: return 0;
    }
}

/* Values of an array-form argument (the last one), normalised the way GL
 * converts integer colours (signed: (2c + 1) / (2^32 - 1)) when asked. */
static bool get_params(interp *ip, const rgl_cmd *cmd, uint32_t need, bool int_colour,
                       float *out)
{
    const rgl_arg *a = &cmd->arg[cmd->nargs - 1];
    if (a->kind == RGL_ARG_SCALAR) {
        if (need != 1)
            return false;
        out[0] = (float)arg_num(a);
        return true;
    }
    if (a->count < need) {
        interp_diag(ip, DIAG_GL_INVALID_VALUE, "invalid value: %u parameters given, %u needed",
                    a->count, need);
        return false;
    }
    bool is_int = a->type == RGL_T_i;
    for (uint32_t k = 0; k < need; k++) {
        double v = a->array[k];
        out[k] = (float)(is_int && int_colour ? (2 * v + 1) / 4294967295.0 : v);
    }
    return true;
}

void interp_color_material_update(interp *ip)
{
    gl_attribs *a = &ip->st.a;
    int faces = face_mask(a->lighting.color_material_face);
    const float *c = a->current.color;
    if (faces == 3 && a->lighting.color_material_mode == GL_AMBIENT_AND_DIFFUSE) {
        /* GL's default, at every glColor of a lit draw: straight through */
        memcpy(a->lighting.material[0].ambient, c, 4 * sizeof *c);
        memcpy(a->lighting.material[0].diffuse, c, 4 * sizeof *c);
        memcpy(a->lighting.material[1].ambient, c, 4 * sizeof *c);
        memcpy(a->lighting.material[1].diffuse, c, 4 * sizeof *c);
        return;
    }
    for (int f = 0; f < 2; f++) {
        if (!(faces & (1 << f)))
            continue;
        gl_material *m = &a->lighting.material[f];
        switch (a->lighting.color_material_mode) {
        case GL_EMISSION: memcpy(m->emission, c, 4 * sizeof *c); break;
        case GL_AMBIENT: memcpy(m->ambient, c, 4 * sizeof *c); break;
        case GL_DIFFUSE: memcpy(m->diffuse, c, 4 * sizeof *c); break;
        case GL_SPECULAR: memcpy(m->specular, c, 4 * sizeof *c); break;
        case GL_AMBIENT_AND_DIFFUSE:
            memcpy(m->ambient, c, 4 * sizeof *c);
            memcpy(m->diffuse, c, 4 * sizeof *c);
            break;
        default: break;
        }
    }
}

/* ---- Colour material ----------------------------------------------------------- */

/* GL 2.1 2.14.3 has the tracked terms follow the current colour from the
 * glEnable on. Mesa 22 (measured with OSMesa, tests/programs/cmat_*.c)
 * keeps what a glMaterial set since the last draw instead: its vertex
 * buffer still holds that glMaterial and writes it over the colour the
 * glEnable copied. Those terms keep the material (the state is stale)
 * until the colour changes: before the first draw, a glColor counts only
 * if the colour differs at the draw (or at a glDisable) from the one
 * current at the glEnable; after a draw, any glColor counts. A glMaterial
 * of a tracked term while colour material is on changes nothing (Mesa's
 * _mesa_Materialfv), and glColorMaterial copies the colour only when it
 * changes the face or mode. */
static void cm_resolve(interp *ip)
{
    if (memcmp(ip->st.a.current.color, ip->st.cm.ref, sizeof ip->st.cm.ref) != 0) {
        ip->st.cm.stale = false;
        interp_color_material_update(ip);
    }
}

void interp_cm_colour(interp *ip)
{
    if (!ip->st.cm.stale) {
        interp_color_material_update(ip);
        return;
    }
    if (!ip->st.cm.drawn && !ip->in_begin)
        return; /* the draw decides (cm_resolve) */
    /* Mesa draws the primitive with each vertex's colour; the vertices
     * before this one took the material. */
    if (ip->in_begin && !ip->prim_skip && ip->scene && ip->scene->nverts > ip->prim_first)
        interp_note(ip, DIAG_NOTE_COLOR_MATERIAL_BEGIN);
    ip->st.cm.stale = false;
    interp_color_material_update(ip);
}

void interp_cm_enable(interp *ip, bool on)
{
    gl_attribs *a = &ip->st.a;
    if (!on) {
        if (ip->st.cm.stale && !ip->st.cm.drawn)
            cm_resolve(ip);
        ip->st.cm.stale = false;
        return;
    }
    int faces = face_mask(a->lighting.color_material_face);
    uint8_t bits = cm_bits(a->lighting.color_material_mode);
    uint8_t kept[2] = {0, 0};
    for (int f = 0; f < 2; f++)
        if (faces & (1 << f))
            kept[f] = ip->st.cm.held[f] & bits;
    ip->st.cm.held[0] = ip->st.cm.held[1] = 0;
    if (!kept[0] && !kept[1]) {
        interp_color_material_update(ip);
        return;
    }
    gl_material m[2];
    memcpy(m, a->lighting.material, sizeof m);
    interp_color_material_update(ip);
    for (int f = 0; f < 2; f++) {
        gl_material *g = &a->lighting.material[f];
        if (kept[f] & SCENE_CM_AMBIENT) memcpy(g->ambient, m[f].ambient, sizeof g->ambient);
        if (kept[f] & SCENE_CM_DIFFUSE) memcpy(g->diffuse, m[f].diffuse, sizeof g->diffuse);
        if (kept[f] & SCENE_CM_SPECULAR) memcpy(g->specular, m[f].specular, sizeof g->specular);
        if (kept[f] & SCENE_CM_EMISSION) memcpy(g->emission, m[f].emission, sizeof g->emission);
    }
    ip->st.cm.stale = true;
    ip->st.cm.drawn = false;
    memcpy(ip->st.cm.ref, a->current.color, sizeof ip->st.cm.ref);
}

void interp_cm_draw(interp *ip)
{
    ip->st.cm.held[0] = ip->st.cm.held[1] = 0;
    if (!ip->st.cm.stale || ip->st.cm.drawn)
        return;
    cm_resolve(ip);
    ip->st.cm.drawn = true;
}

void interp_material(interp *ip, const rgl_cmd *cmd)
{
    GLenum face = arg_enum(cmd, 0), pname = arg_enum(cmd, 1);
    int faces = face_mask(face);
    bool scalar = cmd->arg[2].kind == RGL_ARG_SCALAR;
    float v[4];
    if (!faces) {
        interp_bad_enum(ip, "face", face);
        return;
    }
    uint32_t need = pname == GL_SHININESS ? 1 : (pname == GL_COLOR_INDEXES ? 3 : 4);
    switch (pname) {
    case GL_AMBIENT: case GL_DIFFUSE: case GL_SPECULAR: case GL_EMISSION:
    case GL_AMBIENT_AND_DIFFUSE: case GL_SHININESS: case GL_COLOR_INDEXES:
        break;
    default:
        interp_bad_enum(ip, "material parameter", pname);
        return;
    }
    if (scalar && need != 1) {
        interp_bad_enum(ip, "material parameter for glMaterialf", pname);
        return;
    }
    if (!get_params(ip, cmd, need, pname != GL_SHININESS && pname != GL_COLOR_INDEXES, v))
        return;
    if (pname == GL_SHININESS && !(v[0] >= 0 && v[0] <= 128)) {
        interp_bad_value(ip, "shininess outside [0, 128]");
        return;
    }
    interp_vmat_before_change(ip);
    /* The terms colour material tracks stay as they are (Mesa). */
    const gl_attribs *a = &ip->st.a;
    uint8_t set = cm_bits(pname), tracked = 0;
    int tracked_faces = 0;
    if (a->caps[INTERP_CAP_COLOR_MATERIAL]) {
        tracked = cm_bits(a->lighting.color_material_mode);
        tracked_faces = face_mask(a->lighting.color_material_face);
    }
    for (int f = 0; f < 2; f++) {
        if (!(faces & (1 << f)))
            continue;
        uint8_t skip = tracked_faces & (1 << f) ? tracked : 0;
        ip->st.cm.held[f] |= set & (uint8_t)~skip;
        gl_material *m = &ip->st.a.lighting.material[f];
        if (!(skip & SCENE_CM_AMBIENT) && (pname == GL_AMBIENT || pname == GL_AMBIENT_AND_DIFFUSE))
            memcpy(m->ambient, v, sizeof v);
        if (!(skip & SCENE_CM_DIFFUSE) && (pname == GL_DIFFUSE || pname == GL_AMBIENT_AND_DIFFUSE))
            memcpy(m->diffuse, v, sizeof v);
        if (!(skip & SCENE_CM_SPECULAR) && pname == GL_SPECULAR)
            memcpy(m->specular, v, sizeof v);
        if (!(skip & SCENE_CM_EMISSION) && pname == GL_EMISSION)
            memcpy(m->emission, v, sizeof v);
        if (pname == GL_SHININESS)
            m->shininess = v[0];
        /* colour indexes: no effect in RGBA mode */
    }
}

void interp_colormaterial(interp *ip, const rgl_cmd *cmd)
{
    GLenum face = arg_enum(cmd, 0), mode = arg_enum(cmd, 1);
    if (!face_mask(face)) {
        interp_bad_enum(ip, "face", face);
        return;
    }
    switch (mode) {
    case GL_EMISSION: case GL_AMBIENT: case GL_DIFFUSE: case GL_SPECULAR:
    case GL_AMBIENT_AND_DIFFUSE:
        break;
    default:
        interp_bad_enum(ip, "colour material mode", mode);
        return;
    }
    gl_attribs *a = &ip->st.a;
    bool same = a->lighting.color_material_face == face && a->lighting.color_material_mode == mode;
    a->lighting.color_material_face = face;
    a->lighting.color_material_mode = mode;
    if (a->caps[INTERP_CAP_COLOR_MATERIAL] && !(same && ip->st.cm.stale)) {
        ip->st.cm.stale = false;
        interp_color_material_update(ip);
    }
}

void interp_light(interp *ip, const rgl_cmd *cmd)
{
    GLenum light = arg_enum(cmd, 0), pname = arg_enum(cmd, 1);
    bool scalar = cmd->arg[2].kind == RGL_ARG_SCALAR;
    float v[4];
    if (light < GL_LIGHT0 || light >= GL_LIGHT0 + INTERP_MAX_LIGHTS) {
        interp_bad_enum(ip, "light", light);
        return;
    }
    gl_light *l = &ip->st.a.lighting.light[light - GL_LIGHT0];
    uint32_t need;
    switch (pname) {
    case GL_AMBIENT: case GL_DIFFUSE: case GL_SPECULAR: case GL_POSITION: need = 4; break;
    case GL_SPOT_DIRECTION: need = 3; break;
    case GL_SPOT_EXPONENT: case GL_SPOT_CUTOFF: case GL_CONSTANT_ATTENUATION:
    case GL_LINEAR_ATTENUATION: case GL_QUADRATIC_ATTENUATION: need = 1; break;
    default:
        interp_bad_enum(ip, "light parameter", pname);
        return;
    }
    if (scalar && need != 1) {
        interp_bad_enum(ip, "light parameter for glLightf", pname);
        return;
    }
    bool colour = pname == GL_AMBIENT || pname == GL_DIFFUSE || pname == GL_SPECULAR;
    if (!get_params(ip, cmd, need, colour, v))
        return;
    const mat4 *mv = interp_matrix(ip, INTERP_MV);
    switch (pname) {
    case GL_AMBIENT: memcpy(l->ambient, v, sizeof v); break;
    case GL_DIFFUSE: memcpy(l->diffuse, v, sizeof v); break;
    case GL_SPECULAR: memcpy(l->specular, v, sizeof v); break;
    case GL_POSITION: {
        double in[4] = {v[0], v[1], v[2], v[3]}, o[4];
        mat4_apply(mv, in, o);
        for (int k = 0; k < 4; k++)
            l->position[k] = (float)o[k];
        break;
    }
    case GL_SPOT_DIRECTION: {
        double in[4] = {v[0], v[1], v[2], 0}, o[4];
        mat4_apply(mv, in, o); /* the upper 3x3 only (w = 0) */
        for (int k = 0; k < 3; k++)
            l->spot_direction[k] = (float)o[k];
        break;
    }
    case GL_SPOT_EXPONENT:
        if (!(v[0] >= 0 && v[0] <= 128)) {
            interp_bad_value(ip, "spot exponent outside [0, 128]");
            return;
        }
        l->spot_exponent = v[0];
        break;
    case GL_SPOT_CUTOFF:
        if (!((v[0] >= 0 && v[0] <= 90) || v[0] == 180)) {
            interp_bad_value(ip, "spot cutoff outside [0, 90] and not 180");
            return;
        }
        l->spot_cutoff = v[0];
        break;
    default: /* the attenuations */
        if (!(v[0] >= 0)) {
            interp_bad_value(ip, "negative attenuation");
            return;
        }
        l->attenuation[pname - GL_CONSTANT_ATTENUATION] = v[0];
        break;
    }
}

void interp_lightmodel(interp *ip, const rgl_cmd *cmd)
{
    GLenum pname = arg_enum(cmd, 0);
    float v[4];
    switch (pname) {
    case GL_LIGHT_MODEL_AMBIENT:
        if (cmd->arg[1].kind == RGL_ARG_SCALAR) {
            interp_bad_enum(ip, "light model parameter for glLightModelf", pname);
            return;
        }
        if (get_params(ip, cmd, 4, true, v))
            memcpy(ip->st.a.lighting.model_ambient, v, sizeof v);
        break;
    case GL_LIGHT_MODEL_LOCAL_VIEWER:
        if (get_params(ip, cmd, 1, false, v))
            ip->st.a.lighting.local_viewer = v[0] != 0;
        break;
    case GL_LIGHT_MODEL_TWO_SIDE:
        if (get_params(ip, cmd, 1, false, v))
            ip->st.a.lighting.two_side = v[0] != 0;
        break;
    case GL_LIGHT_MODEL_COLOR_CONTROL:
        if (!get_params(ip, cmd, 1, false, v))
            break;
        if (v[0] != (float)GL_SINGLE_COLOR && v[0] != (float)GL_SEPARATE_SPECULAR_COLOR)
            interp_bad_enum(ip, "colour control", interp_enum_of(v[0]));
        else
            ip->st.a.lighting.color_control = interp_enum_of(v[0]);
        break;
    default:
        interp_bad_enum(ip, "light model parameter", pname);
        break;
    }
}

void interp_fog(interp *ip, const rgl_cmd *cmd)
{
    GLenum pname = arg_enum(cmd, 0);
    float v[4];
    uint32_t need = pname == GL_FOG_COLOR ? 4 : 1;
    switch (pname) {
    case GL_FOG_MODE: case GL_FOG_DENSITY: case GL_FOG_START: case GL_FOG_END:
    case GL_FOG_INDEX: case GL_FOG_COLOR: case GL_FOG_COORD_SRC: case GL_FOG_DISTANCE_MODE_NV:
        break;
    default:
        interp_bad_enum(ip, "fog parameter", pname);
        return;
    }
    if (need == 4 && cmd->arg[1].kind == RGL_ARG_SCALAR) {
        interp_bad_enum(ip, "fog parameter for glFogf", pname);
        return;
    }
    if (!get_params(ip, cmd, need, pname == GL_FOG_COLOR, v))
        return;
    switch (pname) {
    case GL_FOG_MODE: {
        GLenum m = interp_enum_of(v[0]);
        if (m != GL_LINEAR && m != GL_EXP && m != GL_EXP2) {
            interp_bad_enum(ip, "fog mode", m);
            return;
        }
        ip->st.a.fog.mode = m;
        break;
    }
    case GL_FOG_DENSITY:
        if (!(v[0] >= 0)) {
            interp_bad_value(ip, "negative fog density");
            return;
        }
        ip->st.a.fog.density = v[0];
        break;
    case GL_FOG_START: ip->st.a.fog.start = v[0]; break;
    case GL_FOG_END: ip->st.a.fog.end = v[0]; break;
    case GL_FOG_COLOR:
        for (int k = 0; k < 4; k++)
            ip->st.a.fog.color[k] = clamp01(v[k]);
        break;
    case GL_FOG_COORD_SRC:
        if (v[0] != (float)GL_FOG_COORD && v[0] != (float)GL_FRAGMENT_DEPTH) {
            interp_bad_enum(ip, "fog coordinate source", interp_enum_of(v[0]));
            return;
        }
        ip->st.a.fog.coord_src = interp_enum_of(v[0]);
        break;
    case GL_FOG_DISTANCE_MODE_NV: { /* NV_fog_distance, which Mesa has */
        GLenum d = interp_enum_of(v[0]);
        if (d != GL_EYE_RADIAL_NV && d != GL_EYE_PLANE && d != GL_EYE_PLANE_ABSOLUTE_NV) {
            interp_bad_enum(ip, "fog distance mode", d);
            return;
        }
        ip->st.a.fog.distance = d;
        break;
    }
    default: break; /* colour index: no effect here */
    }
}

/* ---- Into the scene ------------------------------------------------------------ */

static uint8_t cm_bits(GLenum mode)
{
    switch (mode) {
    case GL_AMBIENT: return SCENE_CM_AMBIENT;
    case GL_DIFFUSE: return SCENE_CM_DIFFUSE;
    case GL_SPECULAR: return SCENE_CM_SPECULAR;
    case GL_EMISSION: return SCENE_CM_EMISSION;
    case GL_AMBIENT_AND_DIFFUSE: return SCENE_CM_AMBIENT | SCENE_CM_DIFFUSE;
    default: return 0;
    }
}

uint8_t interp_cm_bits(GLenum mode) { return cm_bits(mode); }

static bool light_on(const gl_attribs *a, int i)
{
    return a->caps[INTERP_CAP_LIGHT0 + i] != 0;
}

int32_t interp_lit_material(interp *ip)
{
    const gl_attribs *a = &ip->st.a;
    scene_material m;
    memset(&m, 0, sizeof m);
    m.lightset = interp_lightset_current(ip);
    bool two = a->lighting.two_side;
    for (int f = 0; f < 2; f++) {
        /* One-sided lighting lights back faces with the front material. */
        const gl_material *g = &a->lighting.material[two ? f : 0];
        memcpy(m.ambient[f], g->ambient, sizeof m.ambient[f]);
        memcpy(m.diffuse[f], g->diffuse, sizeof m.diffuse[f]);
        memcpy(m.specular[f], g->specular, sizeof m.specular[f]);
        memcpy(m.emission[f], g->emission, sizeof m.emission[f]);
        m.shininess[f] = g->shininess;
    }
    if (interp_cm_on(ip)) {
        int faces = face_mask(a->lighting.color_material_face);
        uint8_t bits = cm_bits(a->lighting.color_material_mode);
        for (int f = 0; f < 2; f++) {
            if (!(faces & (1 << (two ? f : 0))))
                continue;
            /* Those terms come from each vertex: leave them out of the
             * material so that one material serves every colour. */
            m.color_material[f] = bits;
            if (bits & SCENE_CM_AMBIENT)
                memset(m.ambient[f], 0, sizeof m.ambient[f]);
            if (bits & SCENE_CM_DIFFUSE)
                memset(m.diffuse[f], 0, sizeof m.diffuse[f]);
            if (bits & SCENE_CM_SPECULAR)
                memset(m.specular[f], 0, sizeof m.specular[f]);
            if (bits & SCENE_CM_EMISSION)
                memset(m.emission[f], 0, sizeof m.emission[f]);
        }
    }
    for (int f = 0; f < 2; f++) { /* terms glMaterial varied between vertices */
        uint8_t x = ip->vmat.cm_extra[f];
        m.color_material[f] |= x;
        if (x & SCENE_CM_AMBIENT)
            memset(m.ambient[f], 0, sizeof m.ambient[f]);
        if (x & SCENE_CM_DIFFUSE)
            memset(m.diffuse[f], 0, sizeof m.diffuse[f]);
        if (x & SCENE_CM_SPECULAR)
            memset(m.specular[f], 0, sizeof m.specular[f]);
        if (x & SCENE_CM_EMISSION)
            memset(m.emission[f], 0, sizeof m.emission[f]);
    }
    memcpy(m.model_ambient, a->lighting.model_ambient, sizeof m.model_ambient);
    m.two_sided = two;
    m.local_viewer = a->lighting.local_viewer;
    return scene_material_index(ip->scene, &m);
}

void interp_fix_fog(interp *ip)
{
    scene *s = ip->scene;
    const gl_attribs *a = &ip->st.a;
    scene_fog f;
    memset(&f, 0, sizeof f);
    f.on = true;
    f.mode = interp_scene_fog(a->fog.mode);
    f.density = a->fog.density;
    f.start = a->fog.start;
    f.end = a->fog.end;
    memcpy(f.color, a->fog.color, sizeof f.color);
    f.distance = interp_fog_distance_kind(ip);
    if (!s->fog.on) {
        s->fog = f;
        return;
    }
    /* Only what the mode uses can differ in the picture (GL 2.1 3.10):
     * GL_LINEAR's start and end, GL_EXP's and GL_EXP2's density. */
    scene_fog a0 = s->fog, a1 = f;
    scene_fog *both[2] = {&a0, &a1};
    for (int k = 0; k < 2; k++) {
        if (both[k]->mode == SCENE_FOG_LINEAR)
            both[k]->density = 0;
        else
            both[k]->start = both[k]->end = 0;
    }
    if (memcmp(&a0, &a1, sizeof a0) != 0)
        interp_note(ip, DIAG_NOTE_FOG);
    else if (memcmp(&s->fog, &f, sizeof f) != 0)
        interp_note_held(ip, DIAG_NOTE_FOG, "what changed is unused by the fog mode");
}

/* GL's spot factor of light l (cutoff not 180) for the unit vector vp from
 * the vertex toward the light (GL 2.1 2.14.1). */
static double spot_factor(const gl_light *l, const double vp[3])
{
    const float *sd = l->spot_direction;
    double sl = sqrt((double)sd[0] * sd[0] + (double)sd[1] * sd[1] + (double)sd[2] * sd[2]);
    double cs = sl > 0 ? -(vp[0] * sd[0] + vp[1] * sd[1] + vp[2] * sd[2]) / sl : 0;
    return cs >= cos(l->spot_cutoff * M_PI / 180) ? pow(fmax(cs, 0), l->spot_exponent) : 0;
}

double interp_spot_parallel(const gl_light *l)
{
    if (l->spot_cutoff == 180 || l->position[3] != 0)
        return 1;
    double vp[3] = {l->position[0], l->position[1], l->position[2]};
    double d = sqrt(vp[0] * vp[0] + vp[1] * vp[1] + vp[2] * vp[2]);
    if (!(d > 0) || !isfinite(d))
        return 1; /* no direction: it lights nothing but ambient */
    for (int k = 0; k < 3; k++)
        vp[k] /= d;
    return spot_factor(l, vp);
}

void interp_lit_color(const interp *ip, const double p[3], const double n[3], bool back,
                      const float colour[4], float out[4])
{
    interp_lit_color_peak(ip, p, n, back, colour, out, NULL);
}

void interp_lit_color_peak(const interp *ip, const double p[3], const double n[3], bool back,
                           const float colour[4], float out[4], double *peak)
{
    interp_lit_prep lp;
    interp_lit_prepare(ip, back, &lp);
    interp_lit_prepared(ip, &lp, p, n, colour, out, peak);
}

void interp_lit_prepare(const interp *ip, bool back, interp_lit_prep *lp)
{
    const gl_attribs *a = &ip->st.a;
    int f = back && a->lighting.two_side ? 1 : 0;
    lp->face = f;
    lp->cm = 0;
    if (interp_cm_on(ip) && (face_mask(a->lighting.color_material_face) & (1 << f)))
        lp->cm = cm_bits(a->lighting.color_material_mode);
    lp->local_viewer = a->lighting.local_viewer;
    lp->need_p = lp->local_viewer;
    lp->nlights = 0;
    /* A cache of the interp's own (interp_internal.h): every interp is
     * made writable by interp_create, only this function is handed it const. */
    interp_litdir *dircache = ((interp *)ip)->litdir;
    for (int i = 0; i < INTERP_MAX_LIGHTS; i++) {
        if (!light_on(a, i))
            continue;
        const gl_light *l = &a->lighting.light[i];
        if (l->position[3] != 0) {
            lp->need_p = true;
        } else {
            /* The same arithmetic once per position, not per vertex. */
            interp_litdir *dc = &dircache[i];
            if (!dc->set || memcmp(dc->pos, l->position, sizeof dc->pos) != 0) {
                double *cv = dc->vp;
                for (int k = 0; k < 3; k++)
                    cv[k] = l->position[k];
                dc->d = sqrt(cv[0] * cv[0] + cv[1] * cv[1] + cv[2] * cv[2]);
                if (dc->d > 0)
                    for (int k = 0; k < 3; k++)
                        cv[k] /= dc->d;
                memcpy(dc->pos, l->position, sizeof dc->pos);
                dc->set = true;
                /* The half vector for the infinite viewer (0, 0, 1). */
                for (int k = 0; k < 3; k++)
                    dc->h[k] = cv[k] + (k == 2);
                dc->hl = sqrt(dc->h[0] * dc->h[0] + dc->h[1] * dc->h[1] + dc->h[2] * dc->h[2]);
            }
            if (!(dc->d > 0))
                continue; /* no direction: GL's vector is 0, it adds nothing */
        }
        lp->light[lp->nlights++] = (uint8_t)i;
    }
}

void interp_lit_prepared(const interp *ip, const interp_lit_prep *lp, const double p[3],
                         const double n[3], const float colour[4], float out[4], double *peak)
{
    const gl_attribs *a = &ip->st.a;
    int f = lp->face;
    /* The material's terms, or the colour for those GL_COLOR_MATERIAL
     * takes: pointers, not a copy of the material per vertex. */
    const gl_material *gm = &a->lighting.material[f];
    const float *ma = lp->cm & SCENE_CM_AMBIENT ? colour : gm->ambient;
    const float *md = lp->cm & SCENE_CM_DIFFUSE ? colour : gm->diffuse;
    const float *ms = lp->cm & SCENE_CM_SPECULAR ? colour : gm->specular;
    const float *me = lp->cm & SCENE_CM_EMISSION ? colour : gm->emission;
    float shininess = gm->shininess;
    double nn[3] = {n[0], n[1], n[2]};
    if (f == 1)
        for (int k = 0; k < 3; k++)
            nn[k] = -nn[k];
    double c[3], spec[3] = {0, 0, 0};
    for (int k = 0; k < 3; k++)
        c[k] = me[k] + ma[k] * a->lighting.model_ambient[k];
    const interp_litdir *dircache = ip->litdir;
    for (int li = 0; li < lp->nlights; li++) {
        int i = lp->light[li];
        const gl_light *l = &a->lighting.light[i];
        double vp[3], att = 1, spot = 1, d = 0;
        bool dir = l->position[3] == 0;
        if (!dir) {
            for (int k = 0; k < 3; k++)
                vp[k] = l->position[k] / l->position[3] - p[k];
            d = sqrt(vp[0] * vp[0] + vp[1] * vp[1] + vp[2] * vp[2]);
            double q = l->attenuation[0] + l->attenuation[1] * d + l->attenuation[2] * d * d;
            att = q > 0 ? 1 / q : 0;
            if (!(d > 0))
                continue;
            for (int k = 0; k < 3; k++)
                vp[k] /= d;
        } else {
            memcpy(vp, dircache[i].vp, sizeof vp);
        }
        if (l->spot_cutoff != 180)
            spot = spot_factor(l, vp);
        double nl = nn[0] * vp[0] + nn[1] * vp[1] + nn[2] * vp[2];
        double sp = 0;
        if (nl > 0) {
            double h[3], hl;
            if (dir && !lp->local_viewer) {
                memcpy(h, dircache[i].h, sizeof h);
                hl = dircache[i].hl;
            } else {
                double e[3] = {0, 0, 1};
                if (lp->local_viewer) {
                    double pl = sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
                    for (int k = 0; k < 3; k++)
                        e[k] = pl > 0 ? -p[k] / pl : 0;
                }
                for (int k = 0; k < 3; k++)
                    h[k] = vp[k] + e[k];
                hl = sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
            }
            /* x^0 is 1 for every x: neither pow nor n.h is needed for
             * the default shininess. */
            if (shininess == 0) {
                sp = 1;
            } else {
                double nh = hl > 0 ? (nn[0] * h[0] + nn[1] * h[1] + nn[2] * h[2]) / hl : 0;
                sp = nh > 0 ? pow(nh, shininess) : 0;
            }
        }
        /* nl where positive, else 0 (fmax's value but for the sign of a
         * zero, which the sums and the clamp below do not show). */
        double dl = nl > 0 ? nl : 0;
        for (int k = 0; k < 3; k++) {
            c[k] += att * spot *
                    (ma[k] * l->ambient[k] + dl * md[k] * l->diffuse[k] +
                     sp * ms[k] * l->specular[k]);
            if (peak)
                spec[k] += att * spot * sp * ms[k] * l->specular[k];
        }
    }
    for (int k = 0; k < 3; k++)
        out[k] = clamp01((float)c[k]);
    out[3] = clamp01(md[3]);
    if (peak) { /* the colour GL clamps before texturing: the primary one alone */
        bool sep = a->lighting.color_control != GL_SINGLE_COLOR;
        double q[3];
        for (int k = 0; k < 3; k++)
            q[k] = sep ? c[k] - spec[k] : c[k];
        *peak = fmax(q[0], fmax(q[1], q[2]));
    }
}
