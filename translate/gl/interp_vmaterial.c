/* interp_vmaterial.c: glMaterial between the vertices of a primitive
 * (docs/mapping.md "Lights per object, shadows, Gouraud").
 *
 * GL lights each vertex with the material current when the vertex is
 * issued (GL 1.x 2.13.2: glMaterial is allowed between glBegin and glEnd).
 * The scene gives a run of triangles one material and each vertex one
 * colour, which the writer uses for the terms colour material names. So a
 * primitive whose vertices saw different materials keeps, per vertex, the
 * material it saw; at glEnd the terms that vary are carried by the vertex
 * colour as if GL_COLOR_MATERIAL named them (exact when at each vertex the
 * varying terms are one colour: GL_DIFFUSE alone, GL_AMBIENT_AND_DIFFUSE,
 * GL_EMISSION alone, ...), and the rest of the material is the last
 * vertex's. Anything else (two different varying colours, a varying
 * shininess, varying terms beside colour material's own) is noted and
 * drawn with the last vertex's material.
 */
#include "interp_internal.h"

#include <string.h>

#include "talloc.h"

void interp_vmat_begin(interp *ip)
{
    ip->vmat.changed = false;
    ip->vmat.n = 0;
}

/* Records the current material for vertices up to (not including) k. */
static bool record_to(interp *ip, size_t k)
{
    if (k > ip->vmat.cap && tr_grow((void **)&ip->vmat.mats, &ip->vmat.cap, k, sizeof *ip->vmat.mats) != 0) {
        if (ip->scene)
            ip->scene->failed = true;
        ip->vmat.changed = false;
        return false;
    }
    for (size_t i = ip->vmat.n; i < k; i++)
        memcpy(ip->vmat.mats[i], ip->st.a.lighting.material, sizeof ip->vmat.mats[i]);
    if (k > ip->vmat.n)
        ip->vmat.n = k;
    return true;
}

void interp_vmat_before_change(interp *ip)
{
    if (!ip->in_begin || ip->prim_skip || !ip->scene || ip->prim_mode <= GL_LINE_STRIP)
        return;
    /* The vertices so far saw the material before this change. */
    interp_relit_flush(ip);
    if (record_to(ip, ip->scene->nverts - ip->prim_first))
        ip->vmat.changed = true;
}

void interp_vmat_vertex(interp *ip)
{
    if (ip->vmat.changed) /* the vertex is in the pool already */
        record_to(ip, ip->scene->nverts - ip->prim_first);
}

/* Bits of the terms in which materials a and b differ. */
static uint8_t differ(const gl_material *a, const gl_material *b)
{
    uint8_t d = 0;
    if (memcmp(a->ambient, b->ambient, sizeof a->ambient) != 0) d |= SCENE_CM_AMBIENT;
    if (memcmp(a->diffuse, b->diffuse, sizeof a->diffuse) != 0) d |= SCENE_CM_DIFFUSE;
    if (memcmp(a->specular, b->specular, sizeof a->specular) != 0) d |= SCENE_CM_SPECULAR;
    if (memcmp(a->emission, b->emission, sizeof a->emission) != 0) d |= SCENE_CM_EMISSION;
    return d;
}

static const float *term(const gl_material *m, uint8_t bit)
{
    switch (bit) {
    case SCENE_CM_AMBIENT: return m->ambient;
    case SCENE_CM_DIFFUSE: return m->diffuse;
    case SCENE_CM_SPECULAR: return m->specular;
    default: return m->emission;
    }
}

bool interp_vmat_end(interp *ip, uint32_t n, gl_material saved[2])
{
    if (!ip->vmat.changed)
        return false;
    ip->vmat.changed = false;
    if (ip->vmat.n < n && !record_to(ip, n))
        return false;
    gl_attribs *a = &ip->st.a;
    memcpy(saved, a->lighting.material, 2 * sizeof *saved);
    /* The rest of the material: the last vertex's (a glMaterial after it
     * lights nothing of this primitive). */
    memcpy(a->lighting.material, ip->vmat.mats[n - 1], sizeof ip->vmat.mats[n - 1]);
    if (!a->caps[INTERP_CAP_LIGHTING])
        return true;
    bool two = a->lighting.two_side;
    uint8_t cm = 0;
    if (interp_cm_on(ip))
        cm = interp_cm_bits(a->lighting.color_material_mode);
    uint8_t vary[2] = {0, 0};
    bool shininess = false;
    for (uint32_t i = 0; i + 1 < n; i++)
        for (int f = 0; f < 2; f++) {
            vary[f] |= differ(&ip->vmat.mats[i][f], &ip->vmat.mats[n - 1][f]);
            shininess |= ip->vmat.mats[i][f].shininess != ip->vmat.mats[n - 1][f].shininess &&
                         (f == 0 || two);
        }
    if (!two)
        vary[1] = 0;
    /* The terms colour material tracks come from glColor already. */
    vary[0] &= (uint8_t)~cm;
    vary[1] &= (uint8_t)~cm;
    uint8_t bits = vary[0] | vary[1];
    if (!bits && !shininess)
        return true;
    bool ok = !shininess && !cm;
    uint8_t first = 0;
    for (uint8_t b = 1; b <= SCENE_CM_EMISSION && ok; b <<= 1)
        if (bits & b) {
            first = first ? first : b;
            for (uint32_t i = 0; i < n && ok; i++)
                for (int f = 0; f < 2 && ok; f++)
                    if ((vary[f] & b) &&
                        memcmp(term(&ip->vmat.mats[i][f], b), term(&ip->vmat.mats[i][0], first),
                               3 * sizeof(float)) != 0)
                        ok = false;
        }
    if (!ok) {
        interp_note(ip, DIAG_NOTE_MATERIAL_VERTEX);
        return true;
    }
    scene_vertex *v = ip->scene->verts + ip->prim_first;
    for (uint32_t i = 0; i < n; i++)
        memcpy(v[i].color, term(&ip->vmat.mats[i][0], first), 3 * sizeof(float));
    ip->vmat.cm_extra[0] = vary[0];
    ip->vmat.cm_extra[1] = two ? vary[1] : vary[0];
    return true;
}

void interp_vmat_restore(interp *ip, const gl_material saved[2])
{
    memcpy(ip->st.a.lighting.material, saved, 2 * sizeof *saved);
    ip->vmat.cm_extra[0] = ip->vmat.cm_extra[1] = 0;
}
