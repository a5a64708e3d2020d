/* povwrite_mesh2.c: a mesh of the scene as POV-Ray mesh2 (povwrite_mesh2.h).
 *
 * Equal positions, normals and colours are written once (dedup.h); the
 * meshes of one look and transform come here as one (write_mesh_groups in
 * povwrite.c). A few per-vertex colours go through texture_list with three
 * indices per face, flat faces take one; more, or any in a display list's
 * prototype, go as one image (colour_image_ok), a texel per vertex where
 * the faces form a grid (povwrite_vgrid.h). Faces are written (v0, v2, v1):
 * POV-Ray then calls GL's front side the outside of the face, which keeps
 * `texture` for GL_FRONT and `interior_texture` for GL_BACK. Degenerate
 * faces, which POV-Ray would reject, are left out, as GL draws nothing for
 * them.
 */
#include "povwrite_mesh2.h"

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "dedup.h"
#include "povwrite_clip.h"
#include "povwrite_cube.h"
#include "povwrite_fogsec.h"
#include "povwrite_internal.h"
#include "povwrite_light.h"
#include "povwrite_mipmap.h"
#include "povwrite_multitex.h"
#include "povwrite_pstipple.h"
#include "povwrite_solid.h"
#include "povwrite_texture.h"
#include "talloc.h"

/* numfmt_f32 through the cache; q has NUMFMT_F32_ROOM bytes. */
_Static_assert(NUMFMT_F32_MAX <= sizeof(((fcache_entry *)0)->text) &&
                   sizeof(((fcache_entry *)0)->text) <= NUMFMT_F32_ROOM,
               "the float cache holds every formatted float");
static inline size_t cached_f32(povwriter *w, char *q, float v)
{
    if (w->fcache_off)
        return numfmt_f32(q, v);
    uint32_t bits;
    memcpy(&bits, &v, sizeof bits);
    fcache_entry *e = &w->fcache[(bits * 2654435761u) >> (32 - FCACHE_BITS)];
    if (e->bits == bits && e->len) {
        memcpy(q, e->text, sizeof e->text);
        w->fcache_hits++;
        return e->len;
    }
    size_t n = numfmt_f32(q, v);
    e->bits = bits;
    e->len = (uint32_t)n;
    memcpy(e->text, q, sizeof e->text);
    return n;
}

/* The text of indices below n (at most ITEXT_MAX) ready in w->itext.
 * Returns 0 or -1. */
static int index_text(povwriter *w, size_t n)
{
    n = n < ITEXT_MAX ? n : ITEXT_MAX;
    if (n <= w->nitext)
        return 0;
    if (tr_grow((void **)&w->itext, &w->cap_itext, n, sizeof *w->itext) != 0)
        return -1;
    /* Each number from the one before: the last digit up one, nines
     * carried (digits from the lowest byte, the length on top). */
    uint64_t v = w->nitext ? w->itext[w->nitext - 1] : 0;
    for (size_t i = w->nitext; i < n; i++) {
        if (i == 0) {
            v = (uint64_t)1 << 56 | '0';
        } else {
            unsigned len = (unsigned)(v >> 56), k = len;
            while (k > 0 && (v >> 8 * (k - 1) & 0xff) == '9')
                v -= (uint64_t)9 << 8 * --k; /* '9' -> '0' */
            if (k > 0) {
                v += (uint64_t)1 << 8 * (k - 1);
            } else { /* 99..9 -> 100..0 */
                v = (uint64_t)(len + 1) << 56 | '1';
                for (k = 1; k <= len; k++)
                    v |= (uint64_t)'0' << 8 * k;
            }
        }
        w->itext[i] = v;
    }
    w->nitext = n;
    return 0;
}

/* Index v at q (8 bytes of room past its length). */
static inline size_t put_index(const povwriter *w, char *q, size_t v)
{
    if (v >= w->nitext)
        return numfmt_u64(q, v);
    uint64_t t = w->itext[v];
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__
    t = __builtin_bswap64(t);
#endif
    memcpy(q, &t, sizeof t);
    return (size_t)(w->itext[v] >> 56);
}

/* pre, then "x,y,z", then post, in one reservation (pre and post are
 * literals of the given lengths, at most 32 bytes: always inline, so that
 * their copies are plain moves). */
__attribute__((always_inline)) static inline void
put_entry(povwriter *w, outbuf *ob, const char *pre, size_t npre, const float v[3],
          const char *post, size_t npost)
{
    char *p = outbuf_room(ob, 3 * NUMFMT_F32_ROOM + 72);
    if (!p)
        return;
    char *q = p;
    memcpy(q, pre, npre);
    q += npre;
    q += cached_f32(w, q, v[0]);
    *q++ = ',';
    q += cached_f32(w, q, v[1]);
    *q++ = ',';
    q += cached_f32(w, q, v[2]);
    memcpy(q, post, npost);
    q += npost;
    outbuf_commit(ob, (size_t)(q - p));
}


/* ",\n<u,v>" (a uv entry) through the float cache: uv on a texel grid
 * take few distinct values (a column's, a row's), met again and again. */
static inline void put_uv(povwriter *w, outbuf *ob, float u, float v)
{
    char *p = outbuf_room(ob, 2 * NUMFMT_F32_ROOM + 8);
    if (!p)
        return;
    char *q = p;
    memcpy(q, ",\n<", 3);
    q += 3;
    q += cached_f32(w, q, u);
    *q++ = ',';
    q += cached_f32(w, q, v);
    *q++ = '>';
    outbuf_commit(ob, (size_t)(q - p));
}

#define PUT_ENTRY(w, ob, pre, v, post) \
    put_entry((w), (ob), (pre), sizeof(pre) - 1, (v), (post), sizeof(post) - 1)

/* The n vectors of 3 floats at word `off` of the vertex keys (positions,
 * normals) as ",\n<x,y,z>" entries. A stream whose numbers seldom repeat
 * (normals turned toward the camera, say) stops going through the float
 * cache after its first FCACHE_PROBE entries: each look-up there only
 * missed the cache, and its stores pushed out the numbers that repeat. */
#define FCACHE_PROBE 256

static void put_vectors(povwriter *w, outbuf *ob, const dedup *vd, size_t n, uint32_t off)
{
    size_t hits = w->fcache_hits;
    for (size_t i = 0; i < n; i++) {
        if (i == FCACHE_PROBE && (w->fcache_hits - hits) * 16 < 3 * FCACHE_PROBE)
            w->fcache_off = true; /* under one in sixteen */
        if (!w->fcache_off && i + 4 < n) {
            /* The cache's entries are scattered: the next numbers' fetched now. */
            const uint32_t *b = dedup_key(vd, i + 4) + off;
            for (int k = 0; k < 3; k++)
                __builtin_prefetch(&w->fcache[(b[k] * 2654435761u) >> (32 - FCACHE_BITS)]);
        }
        PUT_ENTRY(w, ob, ",\n<", (const float *)(const void *)(dedup_key(vd, i) + off), ">");
    }
    w->fcache_off = false;
}

/* A vector list's count and entries after its opening: the vertex keys'
 * vectors at word `off`, then those of the corners of the first ndup / 3
 * faces off the grid (w->offg), each a vertex of its own. */
static void put_vector_list(povwriter *w, outbuf *ob, const dedup *vd, size_t ndup, uint32_t off)
{
    outbuf_u64(ob, vd->count + ndup);
    put_vectors(w, ob, vd, vd->count, off);
    for (size_t j = 0; j < ndup / 3; j++)
        for (int k = 0; k < 3; k++)
            PUT_ENTRY(w, ob, ",\n<",
                      (const float *)(const void *)(dedup_key(vd, w->faces[w->offg[j] * 6 + k]) + off),
                      ">");
    outbuf_puts(ob, "}\n");
}

/* ---- Meshes ------------------------------------------------------------------------ */

/* One texture{...} of a run with look and vertex colour c, textured by
 * tx through `pigment` (povwrite_texture.h) when tx is not NULL: GL's
 * texture environment (GL 1.5 table 3.22). */
static void put_surface(povwriter *w, outbuf *ob, const scene_look *look,
                        const scene_texture *tx, const char *pigment, const float c[4], int side)
{
    if (!tx) {
        povlight_texture(&w->light, ob, look, c, side);
        return;
    }
    if (tx->colour_is_texel) { /* REPLACE, DECAL of RGB: the texel, unlit */
        outbuf_puts(ob, "texture{pigment{");
        outbuf_puts(ob, pigment);
        outbuf_puts(ob, "}}");
        return;
    }
    if (tx->env_mode == SCENE_ENV_BLEND || tx->env_mode == SCENE_ENV_ADD) {
        if (look->lit) {
            float kdp[3], tint[3];
            bool tinted = povlight_modulate_tint(&w->light, look, c, kdp, tint);
            char lit[POVMT_PIGMENT_MAX], env[POVMT_PIGMENT_MAX];
            if (povmt_env_lit(tx, w->env_id, tinted ? tint : NULL, lit, sizeof lit, env,
                              sizeof env) == 0) {
                povlight_texture_env(&w->light, ob, look, c, side,
                                     tx->env_mode == SCENE_ENV_BLEND ? lit : NULL,
                                     tinted && tx->env_mode == SCENE_ENV_BLEND ? kdp : NULL, env);
                return;
            }
        } else if (povmt_env_texture(ob, tx, w->env_id, c) == 0) {
            return;
        }
    }
    if (tx->env_mode == SCENE_ENV_DECAL) {
        /* DECAL of RGBA: the texel over the fragment's colour by its alpha;
         * the image's alpha is POV-Ray's transmit, so the layer below
         * shows through by 1 - alpha. */
        outbuf_puts(ob, "texture{");
        povlight_texture_body(&w->light, ob, look, c, side);
        outbuf_puts(ob, "}texture{pigment{");
        outbuf_puts(ob, pigment);
        outbuf_puts(ob, "}}");
        return;
    }
    float kdp[3], tint[3];
    char tp[POVMT_PIGMENT_MAX];
    if (w->per_entry && povlight_modulate_tint(&w->light, look, c, kdp, tint) &&
        povmt_tinted(tx, w->env_id, tint, tp, sizeof tp) == 0) {
        outbuf_puts(ob, "texture{"); /* MODULATE, this entry's diffuse colour per channel */
        povlight_texture_tinted(&w->light, ob, look, c, side, tp, kdp);
        outbuf_putc(ob, '}');
        return;
    }
    outbuf_puts(ob, "texture{"); /* MODULATE: texel times the fragment's colour */
    if (w->tinted)
        povlight_texture_tinted(&w->light, ob, look, c, side, pigment, w->mod_kdp);
    else
        povlight_texture_mapped(&w->light, ob, look, c, side, pigment);
    outbuf_putc(ob, '}');
}

/* The tint of a lit GL_MODULATE mesh's image whose diffuse colour is not
 * grey (povlight_modulate_tint; w->tinted set for put_surface), or NULL. */
static const float *mesh_tint(povwriter *w, const scene_vertex *verts, const scene_tri *tris,
                              size_t nt, const scene_look *look, const scene_texture *tx,
                              const scene_texture *tx1)
{
    w->tinted = w->per_entry = false;
    if (tx1 || tx->env_mode != SCENE_ENV_MODULATE || tx->colour_is_texel || !look->lit)
        return NULL;
    /* GL_COLOR_MATERIAL's diffuse: one colour for the whole mesh, or none. */
    const float *c = verts[look->flat ? tris[0].provoking : tris[0].v[0]].color;
    for (size_t i = 0; i < nt && c; i++)
        for (int k = 0; k < 4 && c; k++) {
            const float *d = verts[k < 3 ? tris[i].v[k] : tris[i].provoking].color;
            if (memcmp(d, c, 3 * sizeof *c) != 0)
                c = NULL;
        }
    w->tinted = povlight_modulate_tint(&w->light, look, c, w->mod_kdp, w->mod_tint);
    /* GL_COLOR_MATERIAL colours that vary: a tint per texture_list entry,
     * through a function of the image (opaque: not under blending). */
    w->per_entry = !c && !w->mip && !w->cube && look->blend == SCENE_BLEND_OPAQUE;
    return w->tinted ? w->mod_tint : NULL;
}

/* Whether a mesh carries its vertex colours as one image (povtex_colours,
 * povtex_colour_grid) rather than a texture_list: a texture object per
 * colour costs POV-Ray time and memory, and each object{} copy of a
 * prototype's mesh2 copies and transforms its whole texture_list, a single
 * texture stays one (docs/mapping.md sections 6 and 9). The colours must
 * vary (outside a prototype, more than COLOUR_IMAGE_MIN_COLOURS of them),
 * be opaque and need no more clamping than POVTEX_CLAMP_MAX; lit, the
 * colour must be GL_AMBIENT_AND_DIFFUSE's alone (the pigment then scales
 * both as GL's colour does), one-sided. Fog and blending keep the list. */
#define COLOUR_IMAGE_MAX_TRIS (1u << 22)
#define COLOUR_IMAGE_MIN_COLOURS 16

/* A corner's colour as 8-bit values in 16-bit lanes, red lowest: taken
 * from the face before when the corner is one of its (strips share two),
 * else made, the colour opaque and in [0, 1]. False when it is not (a
 * line's strip carries GL's colour ramp on past its end, where GL clamps
 * per pixel: 8 bits would clamp the corner). */
static inline bool corner_q(const float *c, const float *const pc[3], const uint64_t pq[3],
                            uint64_t *q)
{
    if (c == pc[0]) {
        *q = pq[0];
    } else if (c == pc[1]) {
        *q = pq[1];
    } else if (c == pc[2]) {
        *q = pq[2];
    } else {
        if (c[3] != 1 || !(c[0] >= 0 && c[0] <= 1 && c[1] >= 0 && c[1] <= 1 && c[2] >= 0 &&
                           c[2] <= 1))
            return false;
        *q = (uint64_t)povtex_quantise(c[0]) | (uint64_t)povtex_quantise(c[1]) << 16 |
             (uint64_t)povtex_quantise(c[2]) << 32;
    }
    return true;
}

/* Whether a smooth face's corners make a colour block (povtex_colour_origin_q):
 * one test sees one whose D = B + C - A needs no clamping (each lane of
 * B + C + 256 - A in 256..511), the others are tried in full. */
static inline bool face_q_ok(const uint64_t q[3])
{
    const uint64_t lanes = 0x0000010001000100ull, high = 0x0000ff00ff00ff00ull;
    if (((q[1] + q[2] + lanes - q[0]) & high) == lanes)
        return true;
    uint8_t q8[3][3];
    for (int k = 0; k < 3; k++)
        for (int h = 0; h < 3; h++)
            q8[k][h] = (uint8_t)(q[k] >> 16 * h);
    return povtex_colour_origin_q(q8) >= 0;
}

static bool colour_image_ok(const povwriter *w, const scene_vertex *verts, const scene_tri *tris,
                            size_t nt, const scene_look *look)
{
    const scene *s = w->light.s;
    if (!s || look->fog || look->blend != SCENE_BLEND_OPAQUE ||
        nt > COLOUR_IMAGE_MAX_TRIS)
        return false;
    if (look->lit) {
        if (look->material < 0 || (size_t)look->material >= s->nmaterials)
            return false;
        const scene_material *m = &s->materials[look->material];
        if (m->two_sided || m->color_material[0] != (SCENE_CM_AMBIENT | SCENE_CM_DIFFUSE) ||
            m->emission[0][0] != 0 || m->emission[0][1] != 0 || m->emission[0][2] != 0)
            return false;
    }
    /* Outside a prototype a few colours stay a texture_list: a handful of
     * textures costs POV-Ray less than an image and a uv per vertex. */
    size_t want = w->in_proto ? 2 : COLOUR_IMAGE_MIN_COLOURS + 1;
    const float *seen[COLOUR_IMAGE_MIN_COLOURS + 1];
    size_t nseen = 0, last = 0;
    const float *pc[3] = {NULL, NULL, NULL};
    uint64_t pq[3] = {0, 0, 0};
    size_t i = 0;
    for (; i < nt && nseen < want; i++) {
        const float *c[3];
        uint64_t q[3];
        for (int k = 0; k < 3; k++) {
            c[k] = verts[look->flat ? tris[i].provoking : tris[i].v[k]].color;
            if (!corner_q(c[k], pc, pq, &q[k]))
                return false;
            if (nseen < want && (nseen == 0 || memcmp(seen[last], c[k], 3 * sizeof *c[k]) != 0)) {
                size_t j = 0;
                while (j < nseen && memcmp(seen[j], c[k], 3 * sizeof *c[k]) != 0)
                    j++;
                if (j == nseen)
                    seen[nseen++] = c[k];
                last = j;
            }
        }
        if (!look->flat && !face_q_ok(q))
            return false;
        memcpy(pc, c, sizeof pc);
        memcpy(pq, q, sizeof pq);
    }
    if (nseen < want)
        return false;
    /* Enough colours seen: the rest is tested alone. */
    for (; i < nt && look->flat; i++)
        if (verts[tris[i].provoking].color[3] != 1)
            return false;
    for (; i < nt; i++) {
        if (i + POOL_AHEAD < nt)
            __builtin_prefetch(verts[tris[i + POOL_AHEAD].v[2]].color);
        const float *c[3] = {verts[tris[i].v[0]].color, verts[tris[i].v[1]].color,
                             verts[tris[i].v[2]].color};
        uint64_t q[3];
        if (!corner_q(c[0], pc, pq, &q[0]) || !corner_q(c[1], pc, pq, &q[1]) ||
            !corner_q(c[2], pc, pq, &q[2]) || !face_q_ok(q))
            return false;
        memcpy(pc, c, sizeof pc);
        memcpy(pq, q, sizeof pq);
    }
    return true;
}

#define UNSET UINT32_MAX
#define MEMO_AHEAD 8
#define BAD (UINT32_MAX - 1)

/* What the vertex keys of a mesh part hold, and how they are made
 * (write_mesh2_part's pass 1). */
typedef struct key_spec {
    const scene_vertex *verts;
    uint32_t lo; /* the part's first pool vertex (w->remap, w->front, w->eye) */
    bool normals, flat_normals, turn, key_colour, vcolour;
    const scene_texture *tx;
    float uv_scale[2], uv_off[2];
    const mat4 *to_eye, *inv;
    uint32_t memo_gen; /* w->vmemo's generation for this part; 0: not used */
} key_spec;

/* The colour looked up last: colours repeat in runs. */
typedef struct colour_memo {
    uint32_t col[4];
    uint32_t ci; /* DEDUP_NONE: none yet */
} colour_memo;

/* c's index in w->col, or DEDUP_NONE when memory ran out. */
static uint32_t colour_index(povwriter *w, colour_memo *m, const float c[4])
{
    uint32_t ck[4];
    memcpy(ck, c, sizeof ck);
    if (m->ci == DEDUP_NONE || memcmp(ck, m->col, sizeof ck) != 0) {
        m->ci = dedup_index(&w->col, ck);
        memcpy(m->col, ck, sizeof ck);
    }
    return m->ci;
}

/* The memo's entry for pool vertex sv facing front (0 or 1). */
static inline vmemo_entry *vmemo_at(const povwriter *w, const scene_vertex *sv, uint8_t front)
{
    uint64_t h = 0x9e3779b97f4a7c15ull * front;
    static const uint64_t mul[5] = {0xc2b2ae3d27d4eb4full, 0x165667b19e3779f9ull,
                                    0xd6e8feb86659fd93ull, 0xff51afd7ed558ccdull,
                                    0xc4ceb9fe1a85ec53ull};
    for (int i = 0; i < 5; i++) {
        uint64_t x;
        memcpy(&x, (const char *)sv->pos + 8 * i, sizeof x);
        h += (x + (uint64_t)i) * mul[i];
    }
    h ^= h >> 29;
    return &w->vmemo[(h * 0x94d049bb133111ebull) >> (64 - VMEMO_BITS)];
}

/* The vertex index of corner k of face t (BAD for a position that is not
 * finite), its key made and looked up; a new vertex's colour is indexed
 * too (vcolour). DEDUP_NONE when memory ran out. Inline: the loop that
 * calls it runs for every corner. */
__attribute__((always_inline)) static inline uint32_t
vertex_index(povwriter *w, const key_spec *ks, colour_memo *memo, const scene_tri *t, int k,
             bool face_front)
{
    const scene_vertex *verts = ks->verts, *sv = &verts[t->v[k]];
    uint32_t v = t->v[k];
    if (!finite3f(sv->pos))
        return BAD;
    vmemo_entry *me = NULL;
    uint32_t tag = 0;
    if (ks->memo_gen) {
        /* A copy of a vertex indexed before whose index is still in the
         * set's window (dedup_index would find it there): that index. */
        me = vmemo_at(w, sv, w->front[v - ks->lo]);
        tag = ks->memo_gen << 1 | w->front[v - ks->lo];
        const dedup *vd = &w->vtx;
        if (me->tag == tag && memcmp(me->raw, sv->pos, sizeof me->raw) == 0 &&
            me->r >= vd->count - vd->live)
            return me->r;
    }
    /* The key: position, normal, colour bits as the vertex holds them
     * (contiguous in scene_vertex). */
    uint32_t ukey[DEDUP_MAX_WORDS];
    memcpy(ukey, sv->pos, 3 * sizeof *ukey);
    uint32_t nk = 3;
    if (ks->normals) {
        const float *n = ks->flat_normals ? verts[t->provoking].normal : sv->normal;
        bool front = ks->flat_normals ? face_front : ks->turn && w->front[v - ks->lo];
        if (!finite3f(n) || (n[0] == 0 && n[1] == 0 && n[2] == 0)) {
            static const float up[3] = {0, 0, 1}; /* POV-Ray normalises */
            memcpy(ukey + 3, up, sizeof up);
        } else if (front) {
            float tn[3];
            povlight_front_normal(&w->light, ks->to_eye, ks->inv,
                                  w->eye + 3 * (size_t)(v - ks->lo), n, tn);
            memcpy(ukey + 3, tn, 3 * sizeof *ukey);
        } else {
            memcpy(ukey + 3, n, 3 * sizeof *ukey);
        }
        if (ks->flat_normals && k == 2) {
            /* POV-Ray draws a smooth triangle whose three normals are
             * equal (within about 1e-5) with its geometric normal: one
             * corner's is tilted by 1e-4, which moves the shading by
             * under 0.1/255. */
            float tn[3];
            memcpy(tn, ukey + 3, sizeof tn);
            int a = 0;
            for (int c = 1; c < 3; c++)
                if (fabsf(tn[c]) < fabsf(tn[a]))
                    a = c;
            tn[a] += 1e-4f * sqrtf(tn[0] * tn[0] + tn[1] * tn[1] + tn[2] * tn[2]);
            memcpy(ukey + 3, tn, sizeof tn);
        }
        nk = 6;
    }
    if (ks->key_colour)
        memcpy(ukey + nk, sv->color, 4 * sizeof *ukey);
    if (ks->tx) {
        float uv[2];
        for (int a = 0; a < 2; a++) {
            uv[a] = sv->tex[a] * ks->uv_scale[a] + ks->uv_off[a];
            if (!isfinite(uv[a]))
                uv[a] = 0;
        }
        memcpy(ukey + nk + (ks->vcolour ? 4 : 0), uv, sizeof uv);
    }
    dedup *vd = &w->vtx;
    size_t before = vd->count;
    uint32_t r = dedup_index(vd, ukey);
    if (r != DEDUP_NONE && ks->vcolour && vd->count != before) { /* a new vertex: its colour */
        if (tr_grow((void **)&w->vcol, &w->cap_vcol, vd->count, sizeof *w->vcol) != 0 ||
            (w->vcol[r] = colour_index(w, memo, sv->color)) == DEDUP_NONE)
            return DEDUP_NONE;
    }
    if (me && r != DEDUP_NONE) {
        memcpy(me->raw, sv->pos, sizeof me->raw);
        me->tag = tag;
        me->r = r;
    }
    return r;
}


/* Pass 1 of write_mesh2_part: every used vertex indexed, the faces GL
 * would draw kept in w->faces (3 vertex, 3 colour indices each; with
 * vimage, the face's place in tris as its first colour). flat: corners
 * take the face's normal (ks->flat_normals); vcolour: ks->vcolour; both
 * constants in each inline copy. Returns the faces kept, or SIZE_MAX when
 * memory ran out. */
__attribute__((always_inline)) static inline size_t
index_faces(povwriter *w, const key_spec *ks, colour_memo *memo, const scene_tri *tris, size_t nt,
            bool flat, bool vcolour, bool vimage, bool flat_colour)
{
    const scene_vertex *verts = ks->verts;
    uint32_t lo = ks->lo;
    size_t kept = 0;
    for (size_t i = 0; i < nt; i++) {
        const scene_tri *t = &tris[i];
        if (ks->memo_gen && i + MEMO_AHEAD < nt) {
            /* The memo's entries are scattered: the one a triangle ahead
             * looks at, fetched now (its last corner: strips' new one). */
            uint32_t pv = tris[i + MEMO_AHEAD].v[2];
            __builtin_prefetch(vmemo_at(w, &verts[pv], w->front[pv - lo]));
        }
        uint32_t *f = w->faces + kept * 6;
        bool face_front = false;
        if (flat && ks->turn) {
            const double *e = w->eye;
            face_front = povlight_front_facing(&w->light, e + 3 * (size_t)(t->v[0] - lo),
                                               e + 3 * (size_t)(t->v[1] - lo),
                                               e + 3 * (size_t)(t->v[2] - lo));
        }
        int k = 0;
        for (; k < 3; k++) {
            uint32_t r;
            if (flat) { /* the corner's normal is the face's */
                r = vertex_index(w, ks, memo, t, k, face_front);
            } else if ((r = w->remap[t->v[k] - lo]) == UNSET) {
                r = vertex_index(w, ks, memo, t, k, false);
                w->remap[t->v[k] - lo] = r;
            }
            if (r == DEDUP_NONE)
                return SIZE_MAX;
            if (r == BAD)
                break;
            f[k] = r;
            if (vcolour)
                f[3 + k] = w->vcol[r];
        }
        if (k < 3 || f[0] == f[1] || f[1] == f[2] || f[0] == f[2])
            continue;
        /* Zero area (collinear): POV-Ray drops such faces with a warning. */
        const float *a = verts[t->v[0]].pos, *b = verts[t->v[1]].pos, *c = verts[t->v[2]].pos;
        double e1[3] = {(double)b[0] - a[0], (double)b[1] - a[1], (double)b[2] - a[2]};
        double e2[3] = {(double)c[0] - a[0], (double)c[1] - a[1], (double)c[2] - a[2]};
        double cx = e1[1] * e2[2] - e1[2] * e2[1], cy = e1[2] * e2[0] - e1[0] * e2[2],
               cz = e1[0] * e2[1] - e1[1] * e2[0];
        if (cx == 0 && cy == 0 && cz == 0)
            continue;
        if (vimage) {
            f[3] = (uint32_t)i; /* the face's colours come from its block */
            f[4] = f[5] = 0;
        } else if (flat_colour) {
            /* One colour, the provoking vertex's. */
            uint32_t ci = colour_index(w, memo, verts[t->provoking].color);
            if (ci == DEDUP_NONE)
                return SIZE_MAX;
            f[3] = f[4] = f[5] = ci;
        } else if (!vcolour) {
            f[3] = f[4] = f[5] = 0;
        }
        kept++;
    }
    return kept;
}

/* One mesh2 being written (write_mesh2_part): its input, what the look
 * asks for, and what each step leaves for the next. */
typedef struct mesh2_part {
    povwriter *w;
    outbuf *ob;
    const scene_vertex *verts;
    const scene_tri *tris;
    size_t nt;
    const scene_look *look;
    const mat4 *to_eye;
    const double *mt_map;
    const scene *sc;
    /* The texture (tx: as drawn; tx0, tx1: the two units' own). */
    const scene_texture *tx, *tx0, *tx1;
    scene_texture txc;
    bool normals, flat_normals, vimage, vcolour, vgrid, key_colour;
    uint32_t lo;  /* the run's vertices: [lo, lo + span) of the pool */
    size_t span;
    int img;      /* the texture's (or colour image's) index in w->tex */
    float uv_scale[2], uv_off[2], uvlo[2], uvhi[2];
    char pigment[POVMIP_PIGMENT_MAX];
    colour_memo memo;
    bool turn;    /* lit normals turned toward the camera */
    mat4 to_eye_inv;
    const mat4 *inv;
    size_t kept;  /* faces GL draws */
    bool colour_list;
    size_t nleft, nvg; /* faces off the grid; uv of grid vertices */
    bool special, named, dup;
    size_t ndup;
} mesh2_part;

/* What the look asks for, and the vertices' stretch of the pool. Returns
 * 1 when there is nothing to write, -1 on memory failure. */
static int part_begin(mesh2_part *p)
{
    povwriter *w = p->w;
    const scene *sc = w->light.s;
    const scene_look *look = p->look;
    const scene_vertex *verts = p->verts;
    const scene_tri *tris = p->tris;
    size_t nt = p->nt;
    p->sc = sc;
    const scene_texture *tx = look->texture >= 0 && sc && (size_t)look->texture < sc->ntextures
                                  ? &sc->textures[look->texture]
                                  : NULL;
    /* A second unit (mt_map: its coordinates from the first's): the pair
     * is one pigment, which the fragment colour multiplies (both
     * GL_MODULATE) or which is the colour (povmt_texel). */
    p->tx0 = tx;
    p->tx1 = NULL;
    if (tx && p->mt_map) {
        p->tx1 = &sc->textures[look->texture1];
        p->txc = *tx;
        p->txc.env_mode = SCENE_ENV_MODULATE;
        p->txc.colour_is_texel = povmt_texel(tx, p->tx1);
        tx = &p->txc;
    }
    p->tx = tx;
    w->tinted = w->per_entry = false;
    p->normals = look->lit;
    p->flat_normals = look->lit && look->flat;
    p->vimage = !tx && colour_image_ok(w, verts, tris, nt, look);
    /* A texel colour that replaces the fragment's needs no vertex colour. */
    p->vcolour = !p->vimage && !look->flat && !(tx && tx->colour_is_texel);
    /* Smooth colours as an image: a vertex's colour is its texel on the grid. */
    p->vgrid = p->vimage && !look->flat;
    p->key_colour = p->vcolour || p->vgrid;
    uint32_t words = 3 + (p->normals ? 3 : 0) + (p->key_colour ? 4 : 0) + (tx ? 2 : 0);
    dedup *vd = &w->vtx;
    if (nt == 0 || (p->to_eye && !mat4_finite(p->to_eye)))
        return 1;
    vd->words = words;
    if (sc)
        povwrite_names(p->ob, sc, look->names);

    /* Vertices of a run sit in one stretch of the pool. */
    uint32_t lo = UINT32_MAX, hi = 0;
    for (size_t i = 0; i < nt; i++)
        for (int k = 0; k < 3; k++) {
            uint32_t v = tris[i].v[k];
            lo = v < lo ? v : lo;
            hi = v > hi ? v : hi;
        }
    for (size_t i = 0; i < nt; i++) {
        uint32_t v = tris[i].provoking;
        lo = v < lo ? v : lo;
        hi = v > hi ? v : hi;
    }
    size_t span = (size_t)hi - lo + 1;
    p->lo = lo;
    p->span = span;
    if (tr_grow((void **)&w->remap, &w->cap_remap, span, sizeof *w->remap) != 0 ||
        tr_grow((void **)&w->faces, &w->cap_faces, nt * 6, sizeof *w->faces) != 0 ||
        dedup_reset(vd, span) != 0 || dedup_reset(&w->col, 64) != 0)
        return -1;
    memset(w->remap, 0xff, span * sizeof *w->remap); /* UNSET */
    return 0;
}

/* The second unit's pigment: the pair as one (povmt_pigment). */
static int part_pigment_pair(mesh2_part *p)
{
    povwriter *w = p->w;
    const scene_look *look = p->look;
    const scene_vertex *verts = p->verts;
    const scene_tri *tris = p->tris;
    const double *mt_map = p->mt_map;
    float lo1[2] = {INFINITY, INFINITY}, hi1[2] = {-INFINITY, -INFINITY};
    for (size_t i = 0; i < p->nt; i++)
        for (int k = 0; k < 3; k++) {
            const float *uv = verts[tris[i].v[k]].tex;
            for (int a = 0; a < 2; a++) {
                double u1 = mt_map[3 * a] * uv[0] + mt_map[3 * a + 1] * uv[1] + mt_map[3 * a + 2];
                if (isfinite(u1)) {
                    lo1[a] = (float)u1 < lo1[a] ? (float)u1 : lo1[a];
                    hi1[a] = (float)u1 > hi1[a] ? (float)u1 : hi1[a];
                }
            }
        }
    float s1[2], o1[2];
    int img1 = povtex_map(&w->tex, p->sc, look->texture1, lo1, hi1, p->tx1->env_mode == SCENE_ENV_DECAL,
                          NULL, s1, o1);
    const scene_tri *t0 = &tris[0];
    const float *cf = verts[look->flat ? t0->provoking : t0->v[0]].color;
    if (img1 < 0 || povmt_pigment(p->ob, &w->tex, (size_t)p->img, (size_t)img1, p->tx0, p->tx1,
                                  p->uv_scale, p->uv_off, s1, o1, mt_map, cf, w->mt_count++,
                                  p->pigment, sizeof p->pigment) != 0)
        return -1;
    return 0;
}

/* Textured: the image, how the coordinates map into it, and the pigment
 * that samples it as GL does (alpha test, cube map, mipmaps, the
 * environments POV-Ray has no finish for, a second unit). */
static int part_pigment(mesh2_part *p)
{
    povwriter *w = p->w;
    outbuf *ob = p->ob;
    const scene *sc = p->sc;
    const scene_look *look = p->look;
    const scene_vertex *verts = p->verts;
    const scene_tri *tris = p->tris;
    size_t nt = p->nt;
    const scene_texture *tx = p->tx, *tx0 = p->tx0, *tx1 = p->tx1;
    /* The run's texture-coordinate range: where the image map goes, and the
     * range the alpha-test and mipmap pigments below cover. */
    float *uvlo = p->uvlo, *uvhi = p->uvhi;
    if (tx) {
        for (size_t i = 0; i < nt; i++)
            for (int k = 0; k < 3; k++) {
                const float *uv = verts[tris[i].v[k]].tex;
                for (int a = 0; a < 2; a++)
                    if (isfinite(uv[a])) {
                        uvlo[a] = uv[a] < uvlo[a] ? uv[a] : uvlo[a];
                        uvhi[a] = uv[a] > uvhi[a] ? uv[a] : uvhi[a];
                    }
            }
        /* The texels' alpha: DECAL blends by it; under blending it is the
         * fragment's (MODULATE, and REPLACE of RGBA), POV-Ray's transmit. */
        bool keep_alpha = (tx0->env_mode == SCENE_ENV_DECAL && !tx0->colour_is_texel) ||
                          look->blend == SCENE_BLEND_ALPHA;
        p->img = povtex_map(&w->tex, sc, look->texture, uvlo, uvhi, keep_alpha,
                            mesh_tint(w, verts, tris, nt, look, tx0, tx1), p->uv_scale, p->uv_off);
        if (p->img < 0)
            return -1;
    }
    _Static_assert(POVMIP_PIGMENT_MAX >= POVMT_PIGMENT_MAX, "pigment room");
    char *pigment = p->pigment;
    size_t img = (size_t)p->img;
    if (tx && !tx1 && povtex_pigment(&w->tex, img, tx, pigment) == 0)
        return -1;
    if (tx && !tx1 && !w->cube && !w->mip && !w->per_entry && scene_alpha_crisp(tx) &&
        tx->env_mode != SCENE_ENV_BLEND && tx->env_mode != SCENE_ENV_ADD) {
        /* The alpha test on the filtered alpha, as GL's per fragment. */
        if (povtex_alpha_pigment(ob, &w->tex, sc, look->texture, img, uvlo, uvhi,
                                 w->mt_count++, pigment, sizeof p->pigment) != 0)
            return -1;
    }
    if (tx && !tx1 && w->cube) {
        /* A cube map: GL's face and texel per pixel from (s, t, r). */
        if (povcube_pigment(w->cube, w->cube_map, pigment, sizeof p->pigment) != 0)
            return -1;
        p->uv_scale[0] = p->uv_scale[1] = 1;
        p->uv_off[0] = p->uv_off[1] = 0;
    }
    if (tx && !tx1 && w->mip) {
        /* Mipmapped: the levels by GL's level of detail, at the mesh's own uv. */
        bool keep_alpha = (tx->env_mode == SCENE_ENV_DECAL && !tx->colour_is_texel) ||
                          look->blend == SCENE_BLEND_ALPHA;
        if (povmip_pigment(ob, &w->tex, sc, look->texture, w->mip, w->mt_count++, uvlo, uvhi,
                           keep_alpha, w->tinted ? w->mod_tint : NULL, pigment,
                           sizeof p->pigment) != 0)
            return -1;
        p->uv_scale[0] = p->uv_scale[1] = 1;
        p->uv_off[0] = p->uv_off[1] = 0;
    }
    if (tx && !tx1 && (tx->env_mode == SCENE_ENV_BLEND || tx->env_mode == SCENE_ENV_ADD || w->per_entry)) {
        w->env_id = w->mt_count++;
        if (povmt_declare(ob, &w->tex, img, tx, w->env_id) != 0)
            return -1;
    }
    if (tx1)
        return part_pigment_pair(p);
    return 0;
}

/* Lit normals on front faces, turned toward the camera where POV-Ray
 * would mirror them (povlight_front_normal). */
static int part_turn(mesh2_part *p)
{
    povwriter *w = p->w;
    const scene_vertex *verts = p->verts;
    const scene_tri *tris = p->tris;
    size_t nt = p->nt;
    const mat4 *to_eye = p->to_eye;
    p->turn = p->normals && !w->in_proto;
    p->inv = p->turn && to_eye && mat4_invert(to_eye, &p->to_eye_inv) ? &p->to_eye_inv : NULL;
    if (!p->turn)
        return 0;
    size_t span = p->span;
    uint32_t lo = p->lo;
    if (tr_grow((void **)&w->front, &w->cap_front, span, 1) != 0 ||
        tr_grow((void **)&w->eye, &w->cap_eye, span * 3, sizeof *w->eye) != 0)
        return -1;
    /* Each vertex goes to eye space once, not once per face (2: not
     * yet), in the same pass as the faces' facing. */
    memset(w->front, 2, span);
    for (size_t i = 0; i < nt; i++) {
        const scene_tri *t = &tris[i];
        if (i + POOL_AHEAD < nt)
            __builtin_prefetch(verts[tris[i + POOL_AHEAD].v[2]].pos);
        double *e[3];
        for (int k = 0; k < 3; k++) {
            uint32_t v = t->v[k] - lo;
            e[k] = w->eye + 3 * (size_t)v;
            if (w->front[v] == 2) {
                povlight_eye_point(to_eye, verts[t->v[k]].pos, e[k]);
                w->front[v] = 0;
            }
        }
        if (povlight_front_facing(&w->light, e[0], e[1], e[2]))
            for (int k = 0; k < 3; k++)
                w->front[t->v[k] - lo] = 1;
    }
    return 0;
}

/* Pass 1: index every used vertex, keep the faces GL would draw (p->kept).
 * Returns -1 on memory failure. */
static int part_index(mesh2_part *p)
{
    povwriter *w = p->w;
    const scene_look *look = p->look;
    const scene_tri *tris = p->tris;
    size_t nt = p->nt;
    const scene_texture *tx = p->tx;
    key_spec ks = {p->verts, p->lo, p->normals, p->flat_normals, p->turn, p->key_colour,
                   p->vcolour, tx, {p->uv_scale[0], p->uv_scale[1]},
                   {p->uv_off[0], p->uv_off[1]}, p->to_eye, p->inv, 0};
    if (p->turn && !p->flat_normals && !tx) { /* turned normals: copies found by vmemo */
        if (!w->vmemo || w->vmemo_gen >= (1u << 30)) {
            if (!w->vmemo && !(w->vmemo = tr_realloc(NULL, sizeof *w->vmemo << VMEMO_BITS)))
                return -1;
            memset(w->vmemo, 0, sizeof *w->vmemo << VMEMO_BITS);
            w->vmemo_gen = 0;
        }
        ks.memo_gen = ++w->vmemo_gen;
    }
    /* One copy of the loop for each kind of corner (faces of their own or
     * vertices shared, a colour index or none). */
    bool vimage = p->vimage;
    bool flat_colour = !vimage && look->flat && !(tx && tx->colour_is_texel);
    colour_memo *memo = &p->memo;
    size_t kept;
    if (p->flat_normals)
        kept = p->vcolour ? index_faces(w, &ks, memo, tris, nt, true, true, vimage, flat_colour)
                          : index_faces(w, &ks, memo, tris, nt, true, false, vimage, flat_colour);
    else
        kept = p->vcolour ? index_faces(w, &ks, memo, tris, nt, false, true, vimage, flat_colour)
                          : index_faces(w, &ks, memo, tris, nt, false, false, vimage, flat_colour);
    if (kept == SIZE_MAX)
        return -1;
    p->kept = kept;
    return 0;
}

/* Colours as an image (p->vimage): on a grid of the vertices where they
 * are smooth, in blocks of three texels per face elsewhere. */
static int part_colour_image(mesh2_part *p)
{
    povwriter *w = p->w;
    const scene_look *look = p->look;
    const scene_vertex *verts = p->verts;
    const scene_tri *tris = p->tris;
    dedup *vd = &w->vtx;
    size_t kept = p->kept;
    size_t nleft = kept, nvg = 0;
    if (p->vgrid) {
        if (tr_grow((void **)&w->vcolp, &w->cap_vcolp, vd->count, sizeof *w->vcolp) != 0)
            return -1;
        for (size_t v = 0; v < vd->count; v++)
            w->vcolp[v] = (const float *)(const void *)(dedup_key(vd, v) + 3 + (p->normals ? 3 : 0));
        if (povgrid_build(&w->grid, w->faces, 6, kept, vd->count, w->vcolp) != 0)
            return -1;
        if (w->grid.ncells > 0) {
            nleft = kept - w->grid.ncells;
            nvg = vd->count;
        }
    }
    int img;
    for (;;) {
        if (tr_grow((void **)&w->vcorner, &w->cap_vcorner, nleft * 3 + 1,
                    sizeof *w->vcorner) != 0 ||
            tr_grow((void **)&w->offg, &w->cap_offg, nleft + 1, sizeof *w->offg) != 0 ||
            tr_grow((void **)&w->vuv, &w->cap_vuv, nvg * 2 + nleft * 6 + 2, sizeof *w->vuv) != 0)
            return -1;
        for (size_t i = 0, j = 0; i < kept; i++) {
            if (nvg && w->grid.in_grid[i])
                continue;
            if (nvg)
                w->offg[j] = (uint32_t)i;
            const scene_tri *t = &tris[w->faces[i * 6 + 3]];
            for (int k = 0; k < 3; k++)
                w->vcorner[3 * j + k] = verts[look->flat ? t->provoking : t->v[k]].color;
            j++;
        }
        img = nvg ? povtex_colour_grid(&w->tex, &w->grid, nvg, w->vuv, w->vcorner, nleft,
                                       w->vuv + 2 * nvg)
                  : povtex_colours(&w->tex, w->vcorner, kept, w->vuv);
        if (img != POVTEX_TOO_LARGE || !nvg)
            break;
        nvg = 0; /* the grid and the blocks past an image's size: blocks alone */
        nleft = kept;
    }
    p->img = img;
    p->nleft = nleft;
    p->nvg = nvg;
    if (img < 0 || povtex_image_pigment(&w->tex, (size_t)img, true, p->pigment) == 0)
        return -1;
    return 0;
}

/* Layered textures (fog, DECAL of RGBA) enter texture_list by name only:
 * their declarations. */
static void part_declare(mesh2_part *p)
{
    povwriter *w = p->w;
    outbuf *ob = p->ob;
    const scene_look *look = p->look;
    if (look->fog && look->fog_own && !look->fog_fixed) { /* the fog coordinate's own plane */
        mat4 fp;
        memset(&fp, 0, sizeof fp);
        for (int k = 0; k < 4; k++)
            fp.m[k * 4 + 2] = look->fog_plane[k];
        povlight_fog_declare(&w->light, ob, "rgl_fog", &fp, SCENE_FOG_ABS_Z);
    } else if (look->fog) {
        povfog_declare(&w->light, ob, "rgl_fog", p->to_eye, look);
    }
    for (size_t i = 0; i < w->col.count; i++) {
        outbuf_puts(ob, "#declare rgl_t");
        outbuf_u64(ob, i);
        outbuf_putc(ob, '=');
        put_surface(w, ob, look, p->tx, p->pigment,
                    (const float *)(const void *)dedup_key(&w->col, i), 0);
        outbuf_puts(ob, look->fog ? "texture{rgl_fog}\n" : "\n");
    }
}

/* mesh2{ and its lists: vertices, normals, uv, the colours' textures. */
static void part_vectors(mesh2_part *p)
{
    povwriter *w = p->w;
    outbuf *ob = p->ob;
    dedup *vd = &w->vtx;
    outbuf_puts(ob, "mesh2{\nvertex_vectors{");
    put_vector_list(w, ob, vd, p->ndup, 0);
    if (p->normals) {
        outbuf_puts(ob, "normal_vectors{");
        put_vector_list(w, ob, vd, p->ndup, 3);
    }
    if (p->tx) { /* parallel to vertex_vectors: taken by face_indices */
        outbuf_puts(ob, "uv_vectors{");
        outbuf_u64(ob, vd->count);
        uint32_t off = 3 + (p->normals ? 3 : 0) + (p->vcolour ? 4 : 0);
        for (size_t i = 0; i < vd->count; i++) {
            const float *uv = (const float *)(const void *)(dedup_key(vd, i) + off);
            put_uv(w, ob, uv[0], uv[1]);
        }
        outbuf_puts(ob, "}\n");
    }
    size_t nuv = p->nvg + p->nleft * 3;
    if (p->vimage) { /* a vertex's texel on the grid, then three per face off it */
        outbuf_puts(ob, "uv_vectors{");
        outbuf_u64(ob, nuv);
        for (size_t i = 0; i < nuv; i++)
            put_uv(w, ob, w->vuv[2 * i], w->vuv[2 * i + 1]);
        outbuf_puts(ob, "}\n");
    }
    if (p->colour_list) {
        outbuf_puts(ob, "texture_list{");
        outbuf_u64(ob, w->col.count);
        for (size_t i = 0; i < w->col.count; i++) {
            const float *c = (const float *)(const void *)dedup_key(&w->col, i);
            if (p->named) {
                outbuf_puts(ob, ",\ntexture{rgl_t");
                outbuf_u64(ob, i);
                outbuf_putc(ob, '}');
            } else if (p->special) {
                outbuf_puts(ob, ",\n");
                put_surface(w, ob, p->look, p->tx, p->pigment, c, 0);
            } else {
                PUT_ENTRY(w, ob, ",\ntexture{pigment{rgb<", c, ">}}");
            }
        }
        outbuf_puts(ob, "}\n");
    }
}

/* Faces as (v0, v2, v1): see the file comment. Without normal_indices,
 * POV-Ray takes the normals by face_indices. */
static const int face_order[3] = {0, 2, 1};

/* face_indices, and the colour image's uv_indices. */
static int part_faces(mesh2_part *p)
{
    povwriter *w = p->w;
    outbuf *ob = p->ob;
    dedup *vd = &w->vtx;
    const int *order = face_order;
    size_t kept = p->kept, nvg = p->nvg, nleft = p->nleft;
    bool dup = p->dup;
    size_t nindex = vd->count + p->ndup > nvg + nleft * 3 ? vd->count + p->ndup : nvg + nleft * 3;
    if (index_text(w, nindex) != 0)
        return -1;
    outbuf_puts(ob, "face_indices{");
    outbuf_u64(ob, kept);
    for (size_t i = 0, j = 0; i < kept; i++) {
        const uint32_t *f = w->faces + i * 6;
        char *r = outbuf_room(ob, 8 * 12);
        if (!r)
            return -1;
        char *q = r;
        memcpy(q, ",\n<", 3);
        q += 3;
        size_t c0 = f[order[0]], c1 = f[order[1]], c2 = f[order[2]];
        if (dup && !w->grid.in_grid[i]) { /* its corners' copies */
            c0 = vd->count + 3 * j + (size_t)order[0];
            c1 = vd->count + 3 * j + (size_t)order[1];
            c2 = vd->count + 3 * j + (size_t)order[2];
            j++;
        }
        q += put_index(w, q, c0);
        *q++ = ',';
        q += put_index(w, q, c1);
        *q++ = ',';
        q += put_index(w, q, c2);
        *q++ = '>';
        if (p->colour_list) {
            if (f[3] == f[4] && f[4] == f[5]) {
                *q++ = ',';
                q += put_index(w, q, f[3]);
            } else {
                for (int k = 0; k < 3; k++) {
                    *q++ = ',';
                    q += put_index(w, q, f[3 + order[k]]);
                }
            }
        }
        outbuf_commit(ob, (size_t)(q - r));
    }
    outbuf_puts(ob, "}\n");
    if (p->vimage && nleft > 0 && !dup) { /* else the uv go by face_indices */
        outbuf_puts(ob, "uv_indices{");
        outbuf_u64(ob, kept);
        for (size_t i = 0, j = 0; i < kept; i++) {
            char *r = outbuf_room(ob, 8 * 12);
            if (!r)
                return -1;
            char *q = r;
            *q++ = ',';
            *q++ = '\n';
            *q++ = '<';
            bool on_grid = nvg && w->grid.in_grid[i];
            for (int k = 0; k < 3; k++) {
                q += put_index(w, q, on_grid ? w->faces[i * 6 + order[k]]
                                             : nvg + 3 * j + (size_t)order[k]);
                *q++ = k < 2 ? ',' : '>';
            }
            j += !on_grid;
            outbuf_commit(ob, (size_t)(q - r));
        }
        outbuf_puts(ob, "}\n");
    }
    return 0;
}

/* The mesh's texture (when not per face), its back, its placement and
 * what cuts it, and the closing brace. */
static void part_finish(mesh2_part *p)
{
    static const float white[4] = {1, 1, 1, 1};
    povwriter *w = p->w;
    outbuf *ob = p->ob;
    const scene *sc = p->sc;
    const scene_look *look = p->look;
    const scene_texture *tx = p->tx;
    const char *pigment = p->pigment;
    const float *c0 = (const float *)(const void *)dedup_key(&w->col, 0);
    if (p->vimage) { /* the image is the colour: white through GL's terms */
        outbuf_puts(ob, "texture{");
        povlight_texture_mapped(&w->light, ob, look, white, 0, pigment);
        outbuf_puts(ob, "}\n");
    } else if (!p->colour_list) {
        if (p->named)
            outbuf_puts(ob, "texture{rgl_t0}");
        else if (p->special)
            put_surface(w, ob, look, tx, pigment, c0, 0);
        else
            povwrite_unlit_texture(ob, c0);
        outbuf_putc(ob, '\n');
    }
    if (look->lit && look->material >= 0 && (size_t)look->material < w->light.s->nmaterials &&
        w->light.s->materials[look->material].two_sided) {
        /* GL_BACK's material on the faces' inner side (see the file
         * comment); one texture for the whole mesh, in the first colour.
         * POV-Ray takes an interior_texture only beside a texture of the
         * whole mesh: with a texture_list, the front one in that colour. */
        if (p->colour_list && !p->vimage) {
            outbuf_puts(ob, "texture{");
            povlight_texture_body(&w->light, ob, look, c0, 0);
            outbuf_puts(ob, "}\n");
        }
        if (tx) { /* the back takes the texture too (GL textures both sides) */
            outbuf_puts(ob, "#declare rgl_back=");
            put_surface(w, ob, look, tx, pigment, c0, 1);
            outbuf_puts(ob, look->fog ? "texture{rgl_fog}\ninterior_texture{rgl_back}\n"
                                      : "\ninterior_texture{rgl_back}\n");
        } else if (look->fog) { /* a layered texture enters by name only */
            outbuf_puts(ob, "#declare rgl_back=");
            povlight_texture(&w->light, ob, look, c0, 1);
            outbuf_puts(ob, "texture{rgl_fog}\ninterior_texture{rgl_back}\n");
        } else {
            outbuf_puts(ob, "interior_texture{");
            povlight_texture_body(&w->light, ob, look, c0, 1);
            outbuf_puts(ob, "}\n");
        }
    }
    if (p->to_eye)
        povwrite_put_matrix(ob, p->to_eye);
    if (sc && !w->in_proto) {
        povwrite_scissor(ob, sc, look); /* after the matrix: in eye space */
        povwrite_clip(ob, sc, look);
        povwrite_stencil(ob, sc, look);
        povwrite_pstipple(ob, sc, look);
    }
    if (w->mesh_no_shadow)
        outbuf_puts(ob, "no_shadow\n");
    outbuf_puts(ob, "}\n");
}

/* A mesh2 of triangles over a vertex pool; to_eye NULL: the vertices are
 * in eye space. Equal vertices (position, and normal and colour where
 * they are written) are written once: one lookup per pool vertex. With
 * normals, normal_vectors runs parallel to vertex_vectors and POV-Ray takes
 * both by face_indices (no normal_indices). A lit flat face carries its
 * provoking vertex's normal at its three corners (GL lights the whole face
 * with it), so its corners are looked up per face. Colours are shared
 * separately, as texture_list entries. Returns -1 on memory failure. */
static int write_mesh2_part(povwriter *w, outbuf *ob, const scene_vertex *verts,
                            const scene_tri *tris, size_t nt, const scene_look *look,
                            const mat4 *to_eye, const double *mt_map)
{
    static const float white[4] = {1, 1, 1, 1};
    mesh2_part p = {.w = w, .ob = ob, .verts = verts, .tris = tris, .nt = nt, .look = look,
                    .to_eye = to_eye, .mt_map = mt_map, .img = -1,
                    .uv_scale = {1, 1}, .uv_off = {0, 0},
                    .uvlo = {INFINITY, INFINITY}, .uvhi = {-INFINITY, -INFINITY},
                    .pigment = "", .memo = {{0}, DEDUP_NONE}};
    int rc = part_begin(&p);
    if (rc != 0)
        return rc > 0 ? 0 : -1;
    if (part_pigment(&p) != 0 || part_turn(&p) != 0 || part_index(&p) != 0)
        return -1;
    const scene_texture *tx = p.tx;
    if (((tx && tx->colour_is_texel) || p.vimage) && colour_index(w, &p.memo, white) == DEDUP_NONE)
        return -1;
    if (p.kept == 0)
        return 0;
    p.colour_list = w->col.count > 1;
    p.nleft = p.kept;
    if (p.vimage && part_colour_image(&p) != 0)
        return -1;

    /* Pass 2: the text. Each entry is written into one reservation. */
    p.special = povlight_special(look) || tx;
    p.named = look->fog || (tx && tx->env_mode == SCENE_ENV_DECAL && !tx->colour_is_texel);
    if (p.named)
        part_declare(&p);
    /* A few faces off the grid: their corners as vertices of their own,
     * with their blocks' uv, so that every uv stays parallel to the
     * vertices and no uv_indices are needed (one index triple a face
     * costs more text than three more vertices for a twelfth of them). */
    p.dup = p.nvg && p.nleft > 0 && p.nleft * 12 < p.kept;
    p.ndup = p.dup ? p.nleft * 3 : 0;
    part_vectors(&p);
    if (part_faces(&p) != 0)
        return -1;
    part_finish(&p);
    return 0;
}

/* Triangles of a curved mipmapped mesh by their rounded level of detail. */
typedef struct mip_face {
    int32_t key; /* lambda * SCENE_MIP_STEPS, rounded */
    uint32_t i;  /* index in the mesh's triangles */
} mip_face;

static int mip_face_cmp(const void *a, const void *b)
{
    const mip_face *x = a, *y = b;
    if (x->key != y->key)
        return x->key < y->key ? -1 : 1;
    return x->i < y->i ? -1 : x->i > y->i;
}

/* A mipmapped mesh: one mesh2 per planar run (lambda per pixel), and one
 * per rounded lambda for the triangles on planes of their own (scene_mip_split). */
static int write_mipmapped(povwriter *w, outbuf *ob, const scene_vertex *verts,
                           const scene_tri *tris, size_t nt, const scene_look *look,
                           const mat4 *to_eye)
{
    const scene *sc = w->light.s;
    const scene_texture *t = &sc->textures[look->texture];
    mip_face *single = NULL;
    scene_tri *group = NULL;
    size_t ns = 0;
    int rc = -1;
    if (nt > SIZE_MAX / sizeof *single || !(single = tr_realloc(NULL, nt * sizeof *single)) ||
        !(group = tr_realloc(NULL, nt * sizeof *group)))
        goto fail;
    for (size_t i = 0; i < nt;) {
        scene_mip_run r;
        size_t run = scene_mip_split(&sc->camera, to_eye, verts, tris + i, nt - i, t->width,
                                  t->height, &r);
        if (r.planar) {
            w->mip = &r;
            int e = write_mesh2_part(w, ob, verts, tris + i, run, look, to_eye, NULL);
            w->mip = NULL;
            if (e != 0)
                goto fail;
        } else {
            double k = r.lambda * SCENE_MIP_STEPS;
            k = k < -1e6 ? -1e6 : k > 1e6 ? 1e6 : k;
            for (size_t j = i; j < i + run; j++) {
                single[ns].key = (int32_t)lround(k);
                single[ns++].i = (uint32_t)j;
            }
        }
        i += run;
    }
    qsort(single, ns, sizeof *single, mip_face_cmp);
    for (size_t a = 0; a < ns;) {
        size_t b = a;
        while (b < ns && single[b].key == single[a].key) {
            group[b - a] = tris[single[b].i];
            b++;
        }
        scene_mip_run r;
        memset(&r, 0, sizeof r);
        r.lambda = (double)single[a].key / SCENE_MIP_STEPS;
        w->mip = &r;
        int e = write_mesh2_part(w, ob, verts, group, b - a, look, to_eye, NULL);
        w->mip = NULL;
        if (e != 0)
            goto fail;
        a = b;
    }
    rc = 0;
fail:
    tr_free(group);
    tr_free(single);
    return rc;
}

/* A mesh: with two texture units, one mesh2 per run of triangles whose
 * second coordinates are one function of their first (povmt_run). */
int povmesh2_write(povwriter *w, outbuf *ob, const scene_vertex *verts,
                       const scene_tri *tris, size_t nt, const scene_look *look,
                       const mat4 *to_eye)
{
    const scene *sc = w->light.s;
    if (sc && look->texture >= 0 && (size_t)look->texture < sc->ntextures && look->texture1 < 0 &&
        sc->textures[look->texture].cube) {
        /* A cube map: one mesh2 per run whose r is one function of (s, t). */
        povcube cube;
        if (povcube_declare(ob, &w->tex, sc, look->texture, w->mt_count++, &cube) != 0)
            return -1;
        while (nt > 0) {
            double map[6];
            size_t run = povmt_run(verts, tris, nt, map);
            w->cube = &cube;
            w->cube_map = map;
            int rc = write_mesh2_part(w, ob, verts, tris, run, look, to_eye, NULL);
            w->cube = NULL;
            if (rc != 0)
                return -1;
            tris += run;
            nt -= run;
        }
        return 0;
    }
    if (sc && look->texture >= 0 && (size_t)look->texture < sc->ntextures && look->texture1 < 0 &&
        sc->textures[look->texture].mip_filter && !w->in_proto) {
        return write_mipmapped(w, ob, verts, tris, nt, look, to_eye);
    }
    if (look->texture < 0 || look->texture1 < 0 || !sc || (size_t)look->texture >= sc->ntextures ||
        (size_t)look->texture1 >= sc->ntextures)
        return write_mesh2_part(w, ob, verts, tris, nt, look, to_eye, NULL);
    while (nt > 0) {
        double map[6];
        size_t run = povmt_run(verts, tris, nt, map);
        if (write_mesh2_part(w, ob, verts, tris, run, look, to_eye, map) != 0)
            return -1;
        tris += run;
        nt -= run;
    }
    return 0;
}
