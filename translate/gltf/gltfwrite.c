/* gltfwrite.c: scene model -> binary glTF 2.0 (gltfwrite.h).
 *
 * The JSON is built in memory outbufs, one per top-level array, and the
 * binary chunk in a byte buffer; gltf_write then joins them into the GLB
 * container. Every accessor has its own buffer view (all 4-byte data, so
 * alignment holds by construction). Meshes are baked into eye space (node
 * matrices in glTF must be TRS, GL's modelview need not be); a display-list
 * prototype is written once in its own space and placed by one node per
 * call when the call's matrix is TRS, baked otherwise.
 */
#include "gltfwrite.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gltfwrite_internal.h"
#include "gltfwrite_solid.h"
#include "pngout.h"
#include "talloc.h"

/* ---- small helpers ----------------------------------------------------------------- */

static void *grow(writer *w, void *p, size_t *cap, size_t need, size_t elem)
{
    if (need <= *cap)
        return p;
    void *q = p;
    if (tr_grow(&q, cap, need, elem) != 0) {
        w->failed = true;
        return NULL;
    }
    return q;
}

static float fin(double v) { return isfinite(v) && fabs(v) < 3e38 ? (float)v : 0.0f; }
static double clamp01(double v) { return v > 0 ? (v < 1 ? v : 1) : 0; }

/* GL's colours are display values; glTF's factors, vertex colours and light
 * colours are linear, and viewers encode to sRGB on output: the exact sRGB
 * EOTF (IEC 61966-2-1) makes an unlit colour come out as GL drew it. Values
 * above 1 (light colours) follow the same power law. */
double gltfw_srgb_linear(double v)
{
    if (!(v > 0) || !isfinite(v))
        return 0;
    return v <= 0.04045 ? v / 12.92 : pow((v + 0.055) / 1.055, 2.4);
}

void gltfw_num(outbuf *ob, double v) { outbuf_f32(ob, fin(v)); }

void gltfw_nums(outbuf *ob, const double *v, int n)
{
    outbuf_putc(ob, '[');
    for (int i = 0; i < n; i++) {
        if (i)
            outbuf_putc(ob, ',');
        gltfw_num(ob, v[i]);
    }
    outbuf_putc(ob, ']');
}

/* A JSON string: quotes, backslashes, control and non-ASCII bytes escaped
 * (the trace's names are not known to be UTF-8). */
static void jstr(outbuf *ob, const char *s)
{
    static const char hex[] = "0123456789abcdef";
    outbuf_putc(ob, '"');
    for (; s && *s; s++) {
        unsigned char c = (unsigned char)*s;
        if (c == '"' || c == '\\') {
            outbuf_putc(ob, '\\');
            outbuf_putc(ob, (char)c);
        } else if (c < 0x20 || c >= 0x7f) {
            char e[6] = {'\\', 'u', '0', '0', hex[c >> 4], hex[c & 15]};
            outbuf_write(ob, e, 6);
        } else {
            outbuf_putc(ob, (char)c);
        }
    }
    outbuf_putc(ob, '"');
}

/* Starts an item of l; returns its index. */
size_t gltfw_item(list *l)
{
    if (l->count)
        outbuf_putc(&l->ob, ',');
    return l->count++;
}

/* A note for extras.notes, once each (text is a static string). */
void gltfw_note(writer *w, const char *text)
{
    for (size_t i = 0; i < w->nnotes && i < GLTF_MAX_NOTES; i++)
        if (w->note_seen[i] == text)
            return;
    if (w->nnotes >= GLTF_MAX_NOTES)
        return;
    w->note_seen[w->nnotes] = text;
    if (w->nnotes++)
        outbuf_putc(&w->notes, ',');
    jstr(&w->notes, text);
}

/* Appends n bytes to the binary chunk (4-aligned); a buffer view over them.
 * Returns the view's index. */
static size_t add_view(writer *w, const void *data, size_t n, int target)
{
    size_t off = w->bin.n, pad = (4 - n % 4) % 4;
    uint8_t *p = grow(w, w->bin.p, &w->bin.cap, off + n + pad, 1);
    if (p) {
        w->bin.p = p;
        memcpy(p + off, data, n);
        memset(p + off + n, 0, pad);
        w->bin.n = off + n + pad;
    }
    size_t k = gltfw_item(&w->views);
    outbuf *o = &w->views.ob;
    outbuf_puts(o, "{\"buffer\":0,\"byteOffset\":");
    outbuf_u64(o, off);
    outbuf_puts(o, ",\"byteLength\":");
    outbuf_u64(o, n);
    if (target) {
        outbuf_puts(o, ",\"target\":");
        outbuf_u64(o, (uint64_t)target);
    }
    outbuf_putc(o, '}');
    return k;
}

/* An accessor of count elements of comps floats (or uint32 indices). */
static size_t add_accessor(writer *w, const void *data, size_t count, int comps, bool indices,
                           bool bounds)
{
    static const char *const type[] = {"", "SCALAR", "VEC2", "VEC3", "VEC4"};
    size_t view = add_view(w, data, count * (size_t)comps * 4, indices ? GLTF_ELEMENT_ARRAY_BUFFER : GLTF_ARRAY_BUFFER);
    size_t k = gltfw_item(&w->accessors);
    outbuf *o = &w->accessors.ob;
    outbuf_puts(o, "{\"bufferView\":");
    outbuf_u64(o, view);
    outbuf_puts(o, ",\"componentType\":");
    outbuf_u64(o, indices ? T_UINT : T_FLOAT);
    outbuf_puts(o, ",\"count\":");
    outbuf_u64(o, count);
    outbuf_puts(o, ",\"type\":\"");
    outbuf_puts(o, type[comps]);
    outbuf_putc(o, '"');
    if (bounds && !indices) {
        /* Exact float bounds: the validator compares them with the data. */
        const float *f = data;
        double lo[4], hi[4];
        for (int c = 0; c < comps; c++)
            lo[c] = hi[c] = count ? f[c] : 0;
        for (size_t i = 0; i < count; i++)
            for (int c = 0; c < comps; c++) {
                double v = f[i * (size_t)comps + (size_t)c];
                lo[c] = v < lo[c] ? v : lo[c];
                hi[c] = v > hi[c] ? v : hi[c];
            }
        outbuf_puts(o, ",\"min\":");
        gltfw_nums(o, lo, comps);
        outbuf_puts(o, ",\"max\":");
        gltfw_nums(o, hi, comps);
    }
    outbuf_putc(o, '}');
    w->st.accessors++;
    return k;
}

/* ---- materials and textures ------------------------------------------------------------ */

static int32_t texture_index(writer *w, int32_t t)
{
    const scene *s = w->s;
    if (t < 0 || (size_t)t >= s->ntextures)
        return -1;
    if (w->tex_index[t] >= 0)
        return w->tex_index[t];
    const scene_texture *tx = &s->textures[t];
    bool alpha = false;
    for (size_t i = 0; tx->rgba && i < (size_t)tx->width * (size_t)tx->height; i++)
        alpha = alpha || tx->rgba[i * 4 + 3] != 255;
    uint8_t *png = NULL;
    size_t n = 0;
    if (!tx->rgba || pngout_encode(tx->rgba, tx->width, tx->height, alpha, &png, &n) != 0) {
        w->failed = true;
        return -1;
    }
    size_t view = add_view(w, png, n, 0);
    free(png);
    size_t img = gltfw_item(&w->images);
    outbuf_puts(&w->images.ob, "{\"mimeType\":\"image/png\",\"bufferView\":");
    outbuf_u64(&w->images.ob, view);
    outbuf_putc(&w->images.ob, '}');
    w->st.images++;
    /* The border colour (GL_CLAMP, GL_CLAMP_TO_BORDER) has no glTF
     * counterpart: clamped to the edge. */
    size_t smp = gltfw_item(&w->samplers);
    outbuf *o = &w->samplers.ob;
    outbuf_puts(o, "{\"magFilter\":");
    outbuf_u64(o, tx->linear ? GLTF_LINEAR : GLTF_NEAREST);
    outbuf_puts(o, ",\"minFilter\":");
    outbuf_u64(o, tx->linear ? GLTF_LINEAR : GLTF_NEAREST);
    outbuf_puts(o, ",\"wrapS\":");
    outbuf_u64(o, tx->repeat_s ? GLTF_REPEAT : GLTF_CLAMP_TO_EDGE);
    outbuf_puts(o, ",\"wrapT\":");
    outbuf_u64(o, tx->repeat_t ? GLTF_REPEAT : GLTF_CLAMP_TO_EDGE);
    outbuf_putc(o, '}');
    if ((!tx->repeat_s && tx->border_s) || (!tx->repeat_t && tx->border_t))
        gltfw_note(w, "the border colour of GL_CLAMP and GL_CLAMP_TO_BORDER: clamped to the edge texel");
    size_t k = gltfw_item(&w->textures);
    outbuf_puts(&w->textures.ob, "{\"sampler\":");
    outbuf_u64(&w->textures.ob, smp);
    outbuf_puts(&w->textures.ob, ",\"source\":");
    outbuf_u64(&w->textures.ob, img);
    outbuf_putc(&w->textures.ob, '}');
    w->tex_index[t] = (int32_t)k;
    return (int32_t)k;
}

/* GL's Blinn-Phong exponent as a GGX roughness: alpha^2 = 2 / (n + 2)
 * (the usual fit of the two lobes' widths), roughness = sqrt(alpha). */
static double roughness_of(double shininess)
{
    double n = shininess > 0 ? shininess : 0;
    return sqrt(sqrt(2.0 / (n + 2.0)));
}

/* The material of a look, shared when equal; vertex_color: COLOR_0 carries
 * the base colour. colour: the draw's GL colour (display values), which
 * GL_COLOR_MATERIAL's ambient term multiplies; NULL for none; varies: it is
 * a mean of colours that differ. Returns its index, or -1 (no memory). */
static int32_t material_index(writer *w, const scene_look *look, bool lines, bool *vertex_color,
                              const float *colour, bool varies)
{
    const scene *s = w->s;
    outbuf m;
    if (outbuf_init(&m, 512, NULL, NULL) != 0) {
        w->failed = true;
        return -1;
    }
    const scene_texture *tx = look->texture >= 0 && (size_t)look->texture < s->ntextures
                                  ? &s->textures[look->texture]
                                  : NULL;
    /* GL_REPLACE (or DECAL) of a colour texture discards the lit colour:
     * the surface shows the texel, unlit. */
    const scene_material *mat = look->lit && !lines && look->material >= 0 &&
                                        (size_t)look->material < s->nmaterials &&
                                        !(tx && tx->colour_is_texel)
                                    ? &s->materials[look->material]
                                    : NULL;
    int32_t tex = tx && !lines ? texture_index(w, look->texture) : -1;
    if (tex >= 0 && tx->env_mode == SCENE_ENV_BLEND)
        gltfw_note(w, "GL_BLEND texture environment: written as GL_MODULATE");
    else if (tex >= 0 && tx->env_mode != SCENE_ENV_MODULATE && !tx->colour_is_texel)
        gltfw_note(w, "a texture environment other than GL_MODULATE, GL_REPLACE or GL_DECAL of a "
                "colour without alpha (GL_DECAL of RGBA, GL_ADD, GL_COMBINE): written as "
                "GL_MODULATE");
    if (look->texture1 >= 0 && !lines)
        gltfw_note(w, "a second texture unit: not written (glTF has one base colour texture)");
    double base[4] = {1, 1, 1, 1};
    *vertex_color = true;
    if (mat && !(mat->color_material[0] & SCENE_CM_DIFFUSE)) {
        for (int c = 0; c < 4; c++)
            base[c] = c < 3 ? gltfw_srgb_linear(clamp01(mat->diffuse[0][c])) : clamp01(mat->diffuse[0][c]);
        *vertex_color = false;
    }
    if (tex >= 0 && tx->colour_is_texel)
        *vertex_color = false; /* GL_REPLACE / GL_DECAL: the texel alone */
    outbuf_puts(&m, "{\"pbrMetallicRoughness\":{\"baseColorFactor\":");
    gltfw_nums(&m, base, 4);
    if (tex >= 0) {
        outbuf_puts(&m, ",\"baseColorTexture\":{\"index\":");
        outbuf_u64(&m, (uint64_t)tex);
        outbuf_putc(&m, '}');
    }
    outbuf_puts(&m, ",\"metallicFactor\":0");
    double spec[3] = {0, 0, 0};
    if (mat) {
        for (int c = 0; c < 3; c++)
            spec[c] = gltfw_srgb_linear(clamp01(mat->specular[0][c]));
        outbuf_puts(&m, ",\"roughnessFactor\":");
        gltfw_num(&m, roughness_of(mat->shininess[0]));
    }
    outbuf_putc(&m, '}');
    if (mat) {
        /* GL's ambient terms are a constant colour added to the surface's,
         * as emission is: both go to emissive (clamped to glTF's [0, 1]). */
        double em[3];
        for (int c = 0; c < 3; c++) {
            double amb = mat->model_ambient[c];
            for (size_t i = 0; i < s->nlights; i++)
                if (s->lights[i].aimed || s->lights[i].set == mat->lightset)
                    amb += s->lights[i].ambient[c];
            /* The ambient term tracking the colour is a constant only
             * for one colour: glTF's emissive cannot vary per vertex. */
            double ma = !(mat->color_material[0] & SCENE_CM_AMBIENT) ? mat->ambient[0][c]
                        : colour && !varies                          ? colour[c]
                                                                     : 0;
            em[c] = gltfw_srgb_linear(clamp01(mat->emission[0][c] + amb * ma));
        }
        if (mat->color_material[0] & SCENE_CM_AMBIENT && varies)
            gltfw_note(w, "GL_COLOR_MATERIAL's ambient term of a draw whose colours vary: not "
                    "written (glTF's emissive is one colour)");
        if (em[0] > 0 || em[1] > 0 || em[2] > 0) {
            outbuf_puts(&m, ",\"emissiveFactor\":");
            gltfw_nums(&m, em, 3);
        }
    }
    if (look->blend == SCENE_BLEND_ALPHA) {
        outbuf_puts(&m, ",\"alphaMode\":\"BLEND\"");
        if (look->filter > 0)
            gltfw_note(w, "blending that multiplies the colour behind (a filter): written as alpha "
                    "blending of the colour, which glTF's BLEND mode has alone");
        if (look->alpha_test != SCENE_ALPHA_OFF)
            gltfw_note(w, "the alpha test of a blended draw: not written (glTF has one alpha mode)");
    } else if (look->alpha_test == SCENE_ALPHA_ABOVE) {
        /* glTF keeps alpha >= cutoff: GL_GEQUAL exactly, GL_GREATER but
         * for alpha equal to the reference */
        outbuf_puts(&m, ",\"alphaMode\":\"MASK\",\"alphaCutoff\":");
        gltfw_num(&m, clamp01(look->alpha_ref));
    } else if (look->alpha_test == SCENE_ALPHA_OTHER) {
        gltfw_note(w, "alpha test other than GL_GREATER/GL_GEQUAL: not written");
    }
    /* GL drew both sides (culled faces never reach the scene). */
    outbuf_puts(&m, ",\"doubleSided\":true");
    if (!mat) {
        outbuf_puts(&m, ",\"extensions\":{\"KHR_materials_unlit\":{}}");
        w->used_unlit = true;
    } else {
        gltfw_note(w, "lit surfaces: glTF viewers light in linear light, GL in display values: "
                "a surface lit at an angle comes out lighter (exact facing the light)");
        /* No specular in GL: no specular lobe (glTF's default F0 = 0.04
         * would add highlights GL never drew). */
        double f = spec[0] > spec[1] ? spec[0] : spec[1];
        f = f > spec[2] ? f : spec[2];
        outbuf_puts(&m, ",\"extensions\":{\"KHR_materials_specular\":{\"specularFactor\":");
        gltfw_num(&m, f > 0 ? 1 : 0);
        if (f > 0) {
            /* GL's highlight peaks at the specular colour; a GGX lobe of
             * alpha^2 = 2 / (n + 2) lit by intensity pi peaks at
             * F0 (n + 2) / 8 (D = 1 / (pi alpha^2), visibility 1/4 facing
             * the light), and glTF's F0 is 0.04 x specularColorFactor
             * (ior 1.5): so the factor is 200 / (n + 2) x the specular
             * colour, at most 25 (F0 = 1). */
            double n = mat->shininess[0] > 0 ? mat->shininess[0] : 0, sc[3];
            for (int c = 0; c < 3; c++) {
                sc[c] = spec[c] * 200.0 / (n + 2.0);
                sc[c] = sc[c] < 25 ? sc[c] : 25;
            }
            outbuf_puts(&m, ",\"specularColorFactor\":");
            gltfw_nums(&m, sc, 3);
        }
        outbuf_puts(&m, "}}");
        w->used_specular = true;
    }
    outbuf_putc(&m, '}');
    outbuf_putc(&m, '\0');
    if (m.failed) {
        w->failed = true;
        outbuf_finish(&m);
        return -1;
    }
    for (size_t i = 0; i < w->materials.count; i++)
        if (strcmp(w->mat_json[i], m.buf) == 0) {
            outbuf_finish(&m);
            return (int32_t)i;
        }
    char **mj = grow(w, w->mat_json, &w->cap_mat_json, w->materials.count + 1, sizeof *mj);
    if (!mj) {
        outbuf_finish(&m);
        return -1;
    }
    w->mat_json = mj;
    size_t k = gltfw_item(&w->materials);
    outbuf_puts(&w->materials.ob, m.buf);
    mj[k] = m.buf; /* owned now */
    w->st.materials++;
    return (int32_t)k;
}

/* ---- primitives ------------------------------------------------------------------ */

static bool reserve_v(writer *w, size_t n)
{
    size_t need = w->nv + n, c = w->cap_v;
    if (need <= c)
        return true;
    size_t c1 = c, c2 = c, c3 = c, c4 = c;
    float *p = grow(w, w->pos, &c1, need, 3 * sizeof(float));
    if (p)
        w->pos = p;
    float *q = p ? grow(w, w->nrm, &c2, need, 3 * sizeof(float)) : NULL;
    if (q)
        w->nrm = q;
    float *r = q ? grow(w, w->col, &c3, need, 4 * sizeof(float)) : NULL;
    if (r)
        w->col = r;
    float *u = r ? grow(w, w->uv, &c4, need, 2 * sizeof(float)) : NULL;
    if (u)
        w->uv = u;
    if (!u)
        return false;
    w->cap_v = c1 < c2 ? c1 : c2;
    w->cap_v = w->cap_v < c3 ? w->cap_v : c3;
    w->cap_v = w->cap_v < c4 ? w->cap_v : c4;
    return true;
}

static bool add_index(writer *w, uint32_t i)
{
    uint32_t *p = grow(w, w->idx, &w->cap_i, w->ni + 1, sizeof *p);
    if (!p)
        return false;
    w->idx = p;
    p[w->ni++] = i;
    return true;
}

/* The normal matrix (inverse transpose of m's 3x3); false when singular. */
static bool normal_matrix(const mat4 *m, double n[3][3])
{
    double a[3][3];
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            a[r][c] = m->m[c * 4 + r];
    double det = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
                 a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
                 a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
    if (!(fabs(det) > 1e-300) || !isfinite(det))
        return false;
    /* cofactor matrix / det = inverse transpose */
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++) {
            int r1 = (r + 1) % 3, r2 = (r + 2) % 3, c1 = (c + 1) % 3, c2 = (c + 2) % 3;
            n[r][c] = (a[r1][c1] * a[r2][c2] - a[r1][c2] * a[r2][c1]) / det;
        }
    return true;
}

/* A look's filter (scene_look.filter: what is behind shows as filter x
 * colour + transmit) as the alpha blending glTF has: what is behind keeps
 * the mean of its weights, the surface adds its own share (noted where
 * the material says BLEND). */
static void filter_as_alpha(const scene_look *look, const float c[4], float out[4])
{
    memcpy(out, c, 4 * sizeof *out);
    if (look->blend != SCENE_BLEND_ALPHA || !(look->filter > 0))
        return;
    double f = look->filter < 1 ? look->filter : 1, t = fmax(0, 1 - f - c[3]), keep = 0;
    for (int k = 0; k < 3; k++)
        keep += (f * c[k] + t) / 3;
    double a = fmin(1, fmax(0, 1 - keep));
    for (int k = 0; k < 3; k++)
        out[k] = a > 0 ? (float)(c[3] * c[k] / a) : 0;
    out[3] = (float)a;
}

/* Appends one vertex to the primitive: position through m (NULL: as is),
 * normal through nm, made unit length (glTF requires it). */
static void push_vertex(writer *w, const double p[3], const double nrm[3], const float col[4],
                        const float uv[2], const mat4 *m, double nm[3][3])
{
    size_t k = w->nv++;
    double q[3] = {p[0], p[1], p[2]}, n[3] = {nrm[0], nrm[1], nrm[2]};
    if (m) {
        double in[4] = {p[0], p[1], p[2], 1}, out[4];
        mat4_apply(m, in, out);
        double ww = out[3] != 0 && isfinite(out[3]) ? out[3] : 1;
        for (int c = 0; c < 3; c++)
            q[c] = out[c] / ww;
        if (nm)
            for (int r = 0; r < 3; r++)
                n[r] = nm[r][0] * nrm[0] + nm[r][1] * nrm[1] + nm[r][2] * nrm[2];
    }
    double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(len > 1e-12) || !isfinite(len)) {
        n[0] = n[1] = 0;
        n[2] = len = 1;
    }
    float nf[3];
    double nl = 0;
    for (int c = 0; c < 3; c++) {
        w->pos[k * 3 + (size_t)c] = fin(q[c]);
        nf[c] = (float)(n[c] / len);
        nl += (double)nf[c] * nf[c];
    }
    nl = sqrt(nl);
    for (int c = 0; c < 3; c++)
        w->nrm[k * 3 + (size_t)c] = (float)(nf[c] / nl);
    for (int c = 0; c < 4; c++)
        w->col[k * 4 + (size_t)c] = (float)(c < 3 ? gltfw_srgb_linear(clamp01(col[c])) : clamp01(col[c]));
    /* GL's t runs up from the image's bottom row, glTF's v down from its top. */
    w->uv[k * 2] = fin(uv[0]);
    w->uv[k * 2 + 1] = fin(1.0 - (double)uv[1]);
}

static bool finite3(const float p[3]) { return isfinite(p[0]) && isfinite(p[1]) && isfinite(p[2]); }

/* Whether a face (mode 4) or a line (mode 1) of the pending primitive has
 * vertices of different colours. */
static bool colours_vary(const writer *w, int mode)
{
    size_t per = mode == 4 ? 3 : mode == 1 ? 2 : 0, n = w->ni ? w->ni : w->nv;
    for (size_t f = 0; per && f + per <= n; f += per) {
        size_t a = w->ni ? w->idx[f] : f;
        for (size_t k = 1; k < per; k++) {
            size_t b = w->ni ? w->idx[f + k] : f + k;
            if (memcmp(&w->col[a * 4], &w->col[b * 4], 3 * sizeof(float)) != 0)
                return true;
        }
    }
    return false;
}

/* Writes the current vertices and indices as a primitive of mode into pj
 * (one JSON object), then empties them. */
static void flush_prim(writer *w, outbuf *pj, int mode, int32_t material, bool vertex_color,
                       bool normals, bool uvs)
{
    if (w->nv == 0)
        return;
    if (vertex_color && colours_vary(w, mode))
        gltfw_note(w, "colours that vary across a face or line: glTF interpolates them in linear "
                "light, GL in display values (mid-way colours come out lighter)");
    size_t pa = add_accessor(w, w->pos, w->nv, 3, false, true);
    size_t na = normals ? add_accessor(w, w->nrm, w->nv, 3, false, false) : 0;
    size_t ca = vertex_color ? add_accessor(w, w->col, w->nv, 4, false, false) : 0;
    size_t ta = uvs ? add_accessor(w, w->uv, w->nv, 2, false, false) : 0;
    size_t ia = w->ni ? add_accessor(w, w->idx, w->ni, 1, true, false) : 0;
    if (pj->len > 1)
        outbuf_putc(pj, ',');
    outbuf_puts(pj, "{\"attributes\":{\"POSITION\":");
    outbuf_u64(pj, pa);
    if (normals) {
        outbuf_puts(pj, ",\"NORMAL\":");
        outbuf_u64(pj, na);
    }
    if (vertex_color) {
        outbuf_puts(pj, ",\"COLOR_0\":");
        outbuf_u64(pj, ca);
    }
    if (uvs) {
        outbuf_puts(pj, ",\"TEXCOORD_0\":");
        outbuf_u64(pj, ta);
    }
    outbuf_putc(pj, '}');
    if (w->ni) {
        outbuf_puts(pj, ",\"indices\":");
        outbuf_u64(pj, ia);
    }
    if (material >= 0) {
        outbuf_puts(pj, ",\"material\":");
        outbuf_u64(pj, (uint64_t)material);
    }
    outbuf_puts(pj, ",\"mode\":");
    outbuf_u64(pj, (uint64_t)mode);
    outbuf_putc(pj, '}');
    w->nv = w->ni = 0;
}

/* The mean of a mesh's vertex colours (GL's values), and whether they
 * differ (then the mean stands for none of them). */
static void mesh_colour(const scene *s, const scene_mesh *me, float mean[4], bool *varies)
{
    double sum[4] = {0, 0, 0, 0};
    size_t n = 0;
    const float *first = NULL;
    for (size_t t = me->first_tri; t < me->first_tri + me->tri_count && t < s->ntris; t++)
        for (int c = 0; c < 3; c++) {
            uint32_t g = s->tris[t].v[c];
            if (g >= s->nverts)
                continue;
            const float *col = s->verts[g].color;
            if (!first)
                first = col;
            else if (memcmp(first, col, 4 * sizeof *col) != 0)
                *varies = true;
            for (int k = 0; k < 4; k++)
                sum[k] += isfinite(col[k]) ? col[k] : 0;
            n++;
        }
    for (int k = 0; k < 4; k++)
        mean[k] = n ? (float)(sum[k] / (double)n) : 0;
}

/* The one colour of a face (GL_FLAT: its provoking vertex's), or NULL
 * when its vertices' colours differ. */
static const float *face_colour(const scene *s, const scene_mesh *me, const scene_tri *tr)
{
    if (me->look.flat)
        return s->verts[tr->provoking].color;
    const float *c0 = s->verts[tr->v[0]].color;
    for (int c = 1; c < 3; c++)
        if (memcmp(c0, s->verts[tr->v[c]].color, 4 * sizeof *c0) != 0)
            return NULL;
    return c0;
}

static bool tri_ok(const scene *s, const scene_tri *tr)
{
    bool ok = tr->provoking < s->nverts;
    for (int c = 0; c < 3 && ok; c++)
        ok = tr->v[c] < s->nverts && finite3(s->verts[tr->v[c]].pos);
    return ok;
}

/* A mesh's faces into the pending primitive: all of them, or (only != NULL)
 * those whose face colour is *only. */
static void mesh_faces(writer *w, const scene_mesh *me, const mat4 *m, double (*nm)[3],
                       const float *only)
{
    const scene *s = w->s;
    if (++w->gen == 0) {
        memset(w->stamp, 0, s->nverts * sizeof *w->stamp);
        w->gen = 1;
    }
    for (size_t t = me->first_tri; t < me->first_tri + me->tri_count && t < s->ntris; t++) {
        const scene_tri *tr = &s->tris[t];
        if (!tri_ok(s, tr))
            continue;
        if (only) {
            const float *fc = face_colour(s, me, tr);
            if (!fc || memcmp(fc, only, 4 * sizeof *fc) != 0)
                continue;
        }
        if (!reserve_v(w, 3))
            continue;
        const scene_vertex *pv = &s->verts[tr->provoking];
        for (int c = 0; c < 3; c++) {
            uint32_t g = tr->v[c];
            const scene_vertex *v = &s->verts[g];
            if (!me->look.flat && w->stamp[g] == w->gen) {
                add_index(w, w->remap[g]);
                continue;
            }
            double p[3] = {v->pos[0], v->pos[1], v->pos[2]};
            /* GL_FLAT: the provoking vertex's colour (and, lit, its normal)
             * for the whole face, so the face's vertices are its own. */
            const scene_vertex *cv = me->look.flat ? pv : v;
            double n[3] = {cv->normal[0], cv->normal[1], cv->normal[2]};
            uint32_t k = (uint32_t)w->nv;
            float fc[4];
            filter_as_alpha(&me->look, cv->color, fc);
            push_vertex(w, p, n, fc, v->tex, m, nm);
            add_index(w, k);
            if (!me->look.flat) {
                w->stamp[g] = w->gen;
                w->remap[g] = k;
            }
        }
    }
}

/* Up to GLTF_CM_COLOURS colours of a mesh whose every face has one colour
 * (a cube of coloured faces): their count, or 0 when a face's colours vary
 * or there are more. */
#define GLTF_CM_COLOURS 16
static size_t face_colours(const scene *s, const scene_mesh *me,
                           const float *out[GLTF_CM_COLOURS])
{
    size_t n = 0;
    for (size_t t = me->first_tri; t < me->first_tri + me->tri_count && t < s->ntris; t++) {
        const scene_tri *tr = &s->tris[t];
        if (!tri_ok(s, tr))
            continue;
        const float *fc = face_colour(s, me, tr);
        if (!fc)
            return 0;
        size_t k = 0;
        while (k < n && memcmp(out[k], fc, 4 * sizeof *fc) != 0)
            k++;
        if (k == n) {
            if (n == GLTF_CM_COLOURS)
                return 0;
            out[n++] = fc;
        }
    }
    return n;
}

/* Whether GL_COLOR_MATERIAL's ambient term follows the colour of a lit look. */
static bool cm_ambient(const scene *s, const scene_look *look)
{
    return look->lit && look->material >= 0 && (size_t)look->material < s->nmaterials &&
           (s->materials[look->material].color_material[0] & SCENE_CM_AMBIENT);
}

/* One scene_mesh as triangle primitives into pj, baked through m (NULL:
 * its vertices as they are): one primitive, or one per face colour when
 * GL_COLOR_MATERIAL's ambient term follows colours that differ from face
 * to face (glTF's emissive is one colour a material). */
static void mesh_prim(writer *w, outbuf *pj, const scene_mesh *me, const mat4 *m)
{
    const scene *s = w->s;
    if (me->look.blend == SCENE_BLEND_INVISIBLE || me->look.alpha_test == SCENE_ALPHA_NEVER ||
        me->tri_count == 0)
        return;
    bool vcol, varies = false, ambient_follows = cm_ambient(s, &me->look);
    float mean[4] = {0, 0, 0, 0};
    if (ambient_follows) /* only GL_COLOR_MATERIAL's ambient term reads the colours */
        mesh_colour(s, me, mean, &varies);
    bool uvs = me->look.texture >= 0 && (size_t)me->look.texture < s->ntextures;
    double nm[3][3];
    bool have_nm = m && normal_matrix(m, nm);
    const float *colours[GLTF_CM_COLOURS];
    size_t ncolours = varies ? face_colours(s, me, colours) : 0;
    for (size_t k = 0; k < ncolours; k++) {
        int32_t mat = material_index(w, &me->look, false, &vcol, colours[k], false);
        mesh_faces(w, me, m, have_nm ? nm : NULL, colours[k]);
        flush_prim(w, pj, 4, mat, vcol, true, uvs);
    }
    if (ncolours)
        return;
    int32_t mat = material_index(w, &me->look, false, &vcol, mean, varies);
    mesh_faces(w, me, m, have_nm ? nm : NULL, NULL);
    flush_prim(w, pj, 4, mat, vcol, true, uvs);
}

/* ---- nodes ----------------------------------------------------------------------- */

static size_t add_mesh(writer *w, outbuf *pj)
{
    size_t k = gltfw_item(&w->meshes);
    outbuf_puts(&w->meshes.ob, "{\"primitives\":[");
    outbuf_write(&w->meshes.ob, pj->buf + 1, pj->len - 1);
    outbuf_puts(&w->meshes.ob, "]}");
    w->st.meshes++;
    return k;
}

static void scene_node(writer *w, size_t node)
{
    uint32_t *p = grow(w, w->scene_nodes, &w->cap_scene_nodes, w->nscene_nodes + 1, sizeof *p);
    if (p) {
        w->scene_nodes = p;
        p[w->nscene_nodes++] = (uint32_t)node;
    }
}

/* A node; mesh, camera, light < 0 for none; matrix NULL for identity. */
size_t gltfw_add_node(writer *w, long mesh, long camera, long light, const double *matrix,
                       const double *rot, const double *trans, const char *name)
{
    size_t k = gltfw_item(&w->nodes);
    outbuf *o = &w->nodes.ob;
    outbuf_putc(o, '{');
    bool first = true;
#define SEP() (first ? (void)(first = false) : outbuf_putc(o, ','))
    if (name) {
        SEP();
        outbuf_puts(o, "\"name\":");
        jstr(o, name);
    }
    if (mesh >= 0) {
        SEP();
        outbuf_puts(o, "\"mesh\":");
        outbuf_u64(o, (uint64_t)mesh);
    }
    if (camera >= 0) {
        SEP();
        outbuf_puts(o, "\"camera\":");
        outbuf_u64(o, (uint64_t)camera);
    }
    if (matrix) {
        SEP();
        outbuf_puts(o, "\"matrix\":");
        gltfw_nums(o, matrix, 16);
    }
    if (rot) {
        SEP();
        outbuf_puts(o, "\"rotation\":");
        gltfw_nums(o, rot, 4);
    }
    if (trans) {
        SEP();
        outbuf_puts(o, "\"translation\":");
        gltfw_nums(o, trans, 3);
    }
    if (light >= 0) {
        SEP();
        outbuf_puts(o, "\"extensions\":{\"KHR_lights_punctual\":{\"light\":");
        outbuf_u64(o, (uint64_t)light);
        outbuf_puts(o, "}}");
    }
#undef SEP
    outbuf_putc(o, '}');
    w->st.nodes++;
    scene_node(w, k);
    return k;
}

/* Whether m is a glTF node matrix: affine, and its 3x3 a rotation times a
 * positive or negative scale along its own axes (columns orthogonal). */
static bool trs_ok(const mat4 *m)
{
    const double *a = m->m;
    if (!mat4_finite(m) || a[3] != 0 || a[7] != 0 || a[11] != 0 || a[15] != 1)
        return false;
    double len[3];
    for (int i = 0; i < 3; i++) {
        const double *c = a + i * 4;
        len[i] = sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
        if (!(len[i] > 1e-6) || len[i] > 1e15)
            return false;
    }
    for (int i = 0; i < 3; i++)
        for (int j = i + 1; j < 3; j++) {
            const double *c = a + i * 4, *d = a + j * 4;
            if (fabs(c[0] * d[0] + c[1] * d[1] + c[2] * d[2]) > 1e-5 * len[i] * len[j])
                return false;
        }
    return true;
}

/* A unit quaternion (x, y, z, w) turning -z to fwd and +y toward up. */
void gltfw_orient(const double fwd_in[3], const double up_in[3], double q[4])
{
    double f[3] = {fwd_in[0], fwd_in[1], fwd_in[2]}, u[3] = {up_in[0], up_in[1], up_in[2]};
    double fl = len3(f);
    if (!(fl > 0) || !isfinite(fl)) {
        f[0] = f[1] = 0;
        f[2] = -1;
        fl = 1;
    }
    for (int c = 0; c < 3; c++)
        f[c] /= fl;
    double back[3] = {-f[0], -f[1], -f[2]};
    double d = dot3(u, back);
    for (int c = 0; c < 3; c++)
        u[c] -= d * back[c];
    double ul = len3(u);
    if (!(ul > 1e-9) || !isfinite(ul)) {
        /* any up perpendicular to fwd */
        double t[3] = {fabs(f[0]) < 0.9 ? 1 : 0, fabs(f[0]) < 0.9 ? 0 : 1, 0};
        cross3(back, t, u);
        cross3(u, back, u);
        ul = len3(u);
    }
    for (int c = 0; c < 3; c++)
        u[c] /= ul;
    double r[3];
    cross3(u, back, r);
    /* columns r, u, back: the rotation matrix -> quaternion */
    double m00 = r[0], m11 = u[1], m22 = back[2], tr = m00 + m11 + m22;
    if (tr > 0) {
        double sq = sqrt(tr + 1) * 2;
        q[3] = sq / 4;
        q[0] = (u[2] - back[1]) / sq;
        q[1] = (back[0] - r[2]) / sq;
        q[2] = (r[1] - u[0]) / sq;
    } else if (m00 > m11 && m00 > m22) {
        double sq = sqrt(1 + m00 - m11 - m22) * 2;
        q[3] = (u[2] - back[1]) / sq;
        q[0] = sq / 4;
        q[1] = (u[0] + r[1]) / sq;
        q[2] = (back[0] + r[2]) / sq;
    } else if (m11 > m22) {
        double sq = sqrt(1 + m11 - m00 - m22) * 2;
        q[3] = (back[0] - r[2]) / sq;
        q[0] = (u[0] + r[1]) / sq;
        q[1] = sq / 4;
        q[2] = (back[1] + u[2]) / sq;
    } else {
        double sq = sqrt(1 + m22 - m00 - m11) * 2;
        q[3] = (r[1] - u[0]) / sq;
        q[0] = (back[0] + r[2]) / sq;
        q[1] = (back[1] + u[2]) / sq;
        q[2] = sq / 4;
    }
    double ql = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    for (int c = 0; c < 4; c++)
        q[c] = (double)(float)(q[c] / ql);
}

/* ---- lines and points ---------------------------------------------------------------- */

static void write_lines_points(writer *w)
{
    const scene *s = w->s;
    outbuf pj;
    if (outbuf_init(&pj, 256, NULL, NULL) != 0) {
        w->failed = true;
        return;
    }
    outbuf_putc(&pj, '[');
    scene_look look;
    memset(&look, 0, sizeof look);
    look.material = look.texture = look.texture1 = -1;
    bool vc;
    static const double zero[3] = {0, 0, 1};
    static const float nouv[2] = {0, 0};
    if (s->nlines) {
        int32_t mat = material_index(w, &look, true, &vc, NULL, false);
        for (size_t i = 0; i < s->nlines; i++) {
            const scene_line *l = &s->lines[i];
            if (!finite3(l->p[0]) || !finite3(l->p[1]) || !reserve_v(w, 2))
                continue;
            for (int e = 0; e < 2; e++) {
                double p[3] = {l->p[e][0], l->p[e][1], l->p[e][2]};
                push_vertex(w, p, zero, l->color[2 * e], nouv, NULL, NULL);
            }
        }
        flush_prim(w, &pj, 1, mat, true, false, false);
    }
    if (s->npoints) {
        int32_t mat = material_index(w, &look, true, &vc, NULL, false);
        for (size_t i = 0; i < s->npoints; i++) {
            const scene_point *pt = &s->points[i];
            if (!finite3(pt->p) || !reserve_v(w, 1))
                continue;
            double p[3] = {pt->p[0], pt->p[1], pt->p[2]};
            push_vertex(w, p, zero, pt->color, nouv, NULL, NULL);
        }
        flush_prim(w, &pj, 0, mat, true, false, false);
    }
    if (pj.len > 1) {
        gltfw_add_node(w, (long)add_mesh(w, &pj), -1, -1, NULL, NULL, NULL, "lines and points");
        gltfw_note(w, "lines and points: glTF draws them one pixel wide");
    }
    outbuf_finish(&pj);
}

/* ---- the meshes ------------------------------------------------------------------------ */

static void write_meshes(writer *w)
{
    const scene *s = w->s;
    outbuf pj;
    if (outbuf_init(&pj, 256, NULL, NULL) != 0) {
        w->failed = true;
        return;
    }
    /* Drawn as themselves: one glTF mesh, baked into eye space. */
    outbuf_putc(&pj, '[');
    for (size_t i = 0; i < s->nmeshes && !w->failed; i++) {
        const scene_mesh *me = &s->meshes[i];
        if (!me->proto)
            mesh_prim(w, &pj, me, me->in_eye ? NULL : &me->to_eye);
    }
    for (size_t i = 0; i < s->nsolids && !w->failed; i++)
        gltf_solid_prim(w, &pj, &s->solids[i]);
    if (pj.len > 1)
        gltfw_add_node(w, (long)add_mesh(w, &pj), -1, -1, NULL, NULL, NULL, "scene");

    /* Prototypes: one mesh in prototype space, one node per call. */
    for (size_t k = 0; k < s->nprotos && !w->failed; k++) {
        const scene_proto *pr = &s->protos[k];
        long mesh = -1;
        for (size_t i = 0; i < s->ninstances && !w->failed; i++) {
            const scene_instance *in = &s->instances[i];
            if (in->proto != k)
                continue;
            bool trs = trs_ok(&in->to_eye);
            if (trs && mesh >= 0) {
                gltfw_add_node(w, mesh, -1, -1, in->to_eye.m, NULL, NULL, NULL);
                w->st.instance_nodes++;
                continue;
            }
            pj.len = 0;
            outbuf_putc(&pj, '[');
            for (size_t m = pr->first_mesh; m < pr->first_mesh + pr->nmeshes && m < s->nmeshes;
                 m++) {
                const scene_mesh *me = &s->meshes[m];
                mat4 full = trs ? me->to_eye : mat4_mul(&in->to_eye, &me->to_eye);
                mesh_prim(w, &pj, me, me->in_eye ? NULL : &full);
            }
            if (pj.len <= 1)
                break; /* nothing visible in it */
            long mk = (long)add_mesh(w, &pj);
            if (trs) {
                mesh = mk;
                gltfw_add_node(w, mesh, -1, -1, in->to_eye.m, NULL, NULL, NULL);
                w->st.instance_nodes++;
            } else {
                gltfw_add_node(w, mk, -1, -1, NULL, NULL, NULL, NULL);
            }
        }
    }
    outbuf_finish(&pj);
}

/* ---- the file ------------------------------------------------------------------------- */

static void put_list(outbuf *j, const char *name, const list *l, bool *first)
{
    if (!l->count)
        return;
    if (!*first)
        outbuf_putc(j, ',');
    *first = false;
    outbuf_putc(j, '"');
    outbuf_puts(j, name);
    outbuf_puts(j, "\":[");
    outbuf_write(j, l->ob.buf, l->ob.len);
    outbuf_putc(j, ']');
}

static void put_u32le(uint8_t *p, uint32_t v)
{
    p[0] = (uint8_t)v;
    p[1] = (uint8_t)(v >> 8);
    p[2] = (uint8_t)(v >> 16);
    p[3] = (uint8_t)(v >> 24);
}

static void write_extras(writer *w, outbuf *j, const gltf_frame_info *info)
{
    const scene *s = w->s;
    outbuf_puts(j, ",\"extras\":{\"background\":");
    double bg[4];
    for (int c = 0; c < 4; c++)
        bg[c] = clamp01(s->background[c]);
    gltfw_nums(j, bg, 4);
    /* glTF cameras have no pixel size: the GL viewport's (or --width/--height) */
    outbuf_puts(j, ",\"imageSize\":[");
    outbuf_i64(j, s->camera.width);
    outbuf_putc(j, ',');
    outbuf_i64(j, s->camera.height);
    outbuf_putc(j, ']');
    if (s->fog.on) {
        outbuf_puts(j, ",\"fog\":{\"mode\":");
        jstr(j, s->fog.mode == SCENE_FOG_EXP    ? "exp"
                : s->fog.mode == SCENE_FOG_EXP2 ? "exp2"
                                                : "linear");
        double f[3] = {s->fog.density, s->fog.start, s->fog.end}, fc[4];
        for (int c = 0; c < 4; c++)
            fc[c] = clamp01(s->fog.color[c]);
        outbuf_puts(j, ",\"density\":");
        gltfw_num(j, f[0]);
        outbuf_puts(j, ",\"start\":");
        gltfw_num(j, f[1]);
        outbuf_puts(j, ",\"end\":");
        gltfw_num(j, f[2]);
        outbuf_puts(j, ",\"color\":");
        gltfw_nums(j, fc, 4);
        if (s->fog.distance != SCENE_FOG_ABS_Z) { /* GL_FOG_DISTANCE_MODE_NV */
            outbuf_puts(j, ",\"distance\":");
            jstr(j, s->fog.distance == SCENE_FOG_RADIAL ? "radial" : "eyePlane");
        }
        outbuf_putc(j, '}');
        gltfw_note(w, "fog: glTF has none (kept in extras.fog)");
    }
    if (s->options.radiosity) {
        /* Global illumination is the renderer's: Blender's Cycles bounces
         * light off surfaces for it (raygl-blender.py). */
        outbuf_puts(j, ",\"radiosity\":true");
        gltfw_note(w, "radiosity: a renderer's setting, kept in extras.radiosity (Blender: diffuse "
                "bounces)");
    }
    if (s->overlay)
        gltfw_note(w, "bitmaps and pixel rectangles: not written");
    if (s->focal_blur || s->antialias_depth)
        gltfw_note(w, "accumulation-buffer effects: not written");
    if (info && info->frame_name) {
        outbuf_puts(j, ",\"frameName\":");
        jstr(j, info->frame_name);
    }
    if (info && info->incomplete) {
        outbuf_puts(j, ",\"incomplete\":");
        jstr(j, info->incomplete);
    }
    outbuf_puts(j, ",\"notes\":[");
    outbuf_write(j, w->notes.buf, w->notes.len);
    outbuf_puts(j, "]}");
}

static int assemble(writer *w, outbuf *ob, const gltf_frame_info *info)
{
    outbuf j;
    if (outbuf_init(&j, 4096, NULL, NULL) != 0)
        return -1;
    outbuf_puts(&j, "{\"asset\":{\"version\":\"2.0\",\"generator\":\"raygl2pov\"");
    if (info && info->source) {
        outbuf_puts(&j, ",\"extras\":{\"source\":");
        jstr(&j, info->source);
        outbuf_puts(&j, ",\"frame\":");
        outbuf_u64(&j, info->frame_index);
        outbuf_putc(&j, '}');
    }
    outbuf_putc(&j, '}');
    if (w->used_unlit || w->used_specular || w->used_lights) {
        outbuf_puts(&j, ",\"extensionsUsed\":[");
        bool first = true;
        const char *ext[] = {w->used_lights ? "KHR_lights_punctual" : NULL,
                             w->used_specular ? "KHR_materials_specular" : NULL,
                             w->used_unlit ? "KHR_materials_unlit" : NULL};
        for (int i = 0; i < 3; i++)
            if (ext[i]) {
                if (!first)
                    outbuf_putc(&j, ',');
                first = false;
                jstr(&j, ext[i]);
            }
        outbuf_putc(&j, ']');
    }
    if (w->used_lights) {
        outbuf_puts(&j, ",\"extensions\":{\"KHR_lights_punctual\":{\"lights\":[");
        outbuf_write(&j, w->lights.ob.buf, w->lights.ob.len);
        outbuf_puts(&j, "]}}");
    }
    outbuf_puts(&j, ",\"scene\":0,\"scenes\":[{\"name\":\"frame\",\"nodes\":[");
    for (size_t i = 0; i < w->nscene_nodes; i++) {
        if (i)
            outbuf_putc(&j, ',');
        outbuf_u64(&j, w->scene_nodes[i]);
    }
    outbuf_puts(&j, "]}],");
    bool first = true;
    put_list(&j, "nodes", &w->nodes, &first);
    put_list(&j, "cameras", &w->cameras, &first);
    put_list(&j, "meshes", &w->meshes, &first);
    put_list(&j, "materials", &w->materials, &first);
    put_list(&j, "textures", &w->textures, &first);
    put_list(&j, "images", &w->images, &first);
    put_list(&j, "samplers", &w->samplers, &first);
    put_list(&j, "accessors", &w->accessors, &first);
    put_list(&j, "bufferViews", &w->views, &first);
    if (w->bin.n) {
        outbuf_puts(&j, ",\"buffers\":[{\"byteLength\":");
        outbuf_u64(&j, w->bin.n);
        outbuf_puts(&j, "}]");
    }
    write_extras(w, &j, info);
    outbuf_putc(&j, '}');
    while (j.len % 4)
        outbuf_putc(&j, ' ');
    int rc = -1;
    uint64_t total = 12 + 8 + (uint64_t)j.len + (w->bin.n ? 8 + (uint64_t)w->bin.n : 0);
    if (!j.failed && !w->failed && total <= UINT32_MAX) {
        uint8_t h[20];
        memcpy(h, "glTF", 4);
        put_u32le(h + 4, 2);
        put_u32le(h + 8, (uint32_t)total);
        put_u32le(h + 12, (uint32_t)j.len);
        put_u32le(h + 16, 0x4E4F534Au); /* JSON */
        outbuf_write(ob, (const char *)h, 20);
        outbuf_write(ob, j.buf, j.len);
        if (w->bin.n) {
            put_u32le(h, (uint32_t)w->bin.n);
            put_u32le(h + 4, 0x004E4942u); /* BIN */
            outbuf_write(ob, (const char *)h, 8);
            outbuf_write(ob, (const char *)w->bin.p, w->bin.n);
        }
        rc = ob->failed ? -1 : 0;
    }
    outbuf_finish(&j);
    return rc;
}

int gltf_write(outbuf *ob, const scene *s, const gltf_frame_info *info, gltf_stats *stats)
{
    writer *w = tr_realloc(NULL, sizeof *w);
    if (!w)
        return -1;
    memset(w, 0, sizeof *w);
    w->s = s;
    list *lists[] = {&w->accessors, &w->views, &w->meshes, &w->nodes, &w->materials,
                     &w->textures, &w->images, &w->samplers, &w->lights, &w->cameras};
    bool ok = outbuf_init(&w->notes, 256, NULL, NULL) == 0;
    for (size_t i = 0; i < sizeof lists / sizeof lists[0]; i++)
        ok = outbuf_init(&lists[i]->ob, 256, NULL, NULL) == 0 && ok;
    size_t nv = s->nverts ? s->nverts : 1, nt = s->ntextures ? s->ntextures : 1;
    w->remap = ok ? tr_realloc(NULL, nv * sizeof *w->remap) : NULL;
    w->stamp = w->remap ? tr_realloc(NULL, nv * sizeof *w->stamp) : NULL;
    w->tex_index = w->stamp ? tr_realloc(NULL, nt * sizeof *w->tex_index) : NULL;
    int rc = -1;
    if (w->tex_index) {
        memset(w->stamp, 0, nv * sizeof *w->stamp);
        for (size_t i = 0; i < nt; i++)
            w->tex_index[i] = -1;
        gltfw_write_camera(w);
        gltfw_write_lights(w);
        write_meshes(w);
        write_lines_points(w);
        for (size_t i = 0; i < sizeof lists / sizeof lists[0]; i++)
            w->failed = w->failed || lists[i]->ob.failed;
        if (!w->failed && !w->notes.failed)
            rc = assemble(w, ob, info);
    }
    if (stats)
        *stats = w->st;
    for (size_t i = 0; i < sizeof lists / sizeof lists[0]; i++)
        outbuf_finish(&lists[i]->ob);
    outbuf_finish(&w->notes);
    for (size_t i = 0; i < w->materials.count && w->mat_json; i++)
        tr_free(w->mat_json[i]);
    tr_free(w->mat_json);
    tr_free(w->remap);
    tr_free(w->stamp);
    tr_free(w->tex_index);
    tr_free(w->pos);
    tr_free(w->nrm);
    tr_free(w->col);
    tr_free(w->uv);
    tr_free(w->idx);
    tr_free(w->bin.p);
    tr_free(w->scene_nodes);
    tr_free(w);
    return rc;
}

/* For gltfwrite_solid.c: the primitive machinery, through narrow calls. */
bool gltf_solid_reserve(writer *w, size_t n) { return reserve_v(w, n); }
size_t gltf_solid_count(const writer *w) { return w->nv; }
void gltf_solid_vertex(writer *w, const double p[3], const double n[3], const float col[4],
                       const mat4 *m)
{
    static const float uv[2] = {0, 0};
    double nm[3][3];
    memcpy(w->solid_colour, col, sizeof w->solid_colour);
    push_vertex(w, p, n, col, uv, m, normal_matrix(m, nm) ? nm : NULL);
}
void gltf_solid_index(writer *w, uint32_t i) { add_index(w, i); }
void gltf_solid_flush(writer *w, outbuf *pj, const scene_look *look)
{
    bool vc;
    if (look->blend == SCENE_BLEND_INVISIBLE || look->alpha_test == SCENE_ALPHA_NEVER) {
        w->nv = w->ni = 0;
        return;
    }
    /* a solid is drawn in one colour */
    int32_t mat = material_index(w, look, false, &vc, w->nv ? w->solid_colour : NULL, false);
    flush_prim(w, pj, 4, mat, vc, true, false);
}
