/* interp_array.c: vertex arrays.
 *
 * The recorder resolves every array a draw reads when the draw is made: it
 * writes @ArrayData(array, first, size, type, data) for each enabled array
 * (the elements from `first` on, packed, whether they came from client
 * memory or from a buffer object) right before glDrawArrays,
 * glDrawElements, glDrawRangeElements, glMultiDraw* or glArrayElement, and
 * the index data with the draw. So a draw here reads only the @ArrayData
 * records before it, and the pointer, client-state and buffer-object calls
 * carry nothing a draw needs (frames translate on their own, whatever
 * buffers earlier frames filled). A draw is what GL 1.x 2.8 defines it to
 * be: glBegin(mode), glArrayElement(i) for each index, glEnd; each element
 * sets the current edge flag, texture coordinates, colour and normal from
 * the enabled arrays and then issues the vertex. GL leaves the current
 * values of the enabled arrays indeterminate after a draw (2.8); Mesa
 * keeps the values from before it, and so the materials colour material
 * tracks (checked with OSMesa 22.3.6): a draw restores them. Only
 * glArrayElement keeps the element's.
 */
#include "interp_internal.h"

#include <string.h>

enum {
    ARR_VERTEX, ARR_NORMAL, ARR_COLOR, ARR_TEXCOORD, ARR_EDGEFLAG, ARR_FOGCOORD, ARR_SECONDARY,
    ARR_COUNT
};
_Static_assert(ARR_COUNT == sizeof ((interp *)0)->arrays / sizeof ((interp *)0)->arrays[0],
               "interp.arrays out of step");

static int array_slot(GLenum array)
{
    switch (array) {
    case GL_VERTEX_ARRAY: return ARR_VERTEX;
    case GL_NORMAL_ARRAY: return ARR_NORMAL;
    case GL_COLOR_ARRAY: return ARR_COLOR;
    case GL_TEXTURE_COORD_ARRAY: return ARR_TEXCOORD;
    case GL_EDGE_FLAG_ARRAY: return ARR_EDGEFLAG;
    case GL_FOG_COORD_ARRAY: return ARR_FOGCOORD;
    case GL_SECONDARY_COLOR_ARRAY: return ARR_SECONDARY;
    default: return -1;
    }
}

static size_t type_bytes(GLenum type)
{
    switch (type) {
    case GL_BYTE: case GL_UNSIGNED_BYTE: return 1;
    case GL_SHORT: case GL_UNSIGNED_SHORT: return 2;
    case GL_INT: case GL_UNSIGNED_INT: case GL_FLOAT: return 4;
    case GL_DOUBLE: return 8;
    default: return 0;
    }
}

void interp_arrays_forget(interp *ip)
{
    for (int k = 0; k < ARR_COUNT; k++)
        ip->arrays[k].set = false;
    for (int k = 0; k < INTERP_TEX_UNITS; k++)
        ip->unit_tc[k].set = false;
}

/* @ArrayData(array, first, size, type, data). */
void interp_arraydata(interp *ip, const rgl_cmd *cmd)
{
    GLenum array = arg_enum(cmd, 0);
    int64_t first = cmd->arg[1].v.i, size = cmd->arg[2].v.i;
    GLenum type = arg_enum(cmd, 3);
    const rgl_arg *blob = &cmd->arg[4];
    int slot = array_slot(array);
    size_t ts = type_bytes(type);
    if (slot < 0) {
        interp_bad_enum(ip, "client array", array);
        return;
    }
    struct interp_array_data *a = &ip->arrays[slot];
    if (slot == ARR_TEXCOORD && ip->st.client_unit > 0 && ip->st.client_unit < INTERP_TEX_UNITS)
        a = &ip->unit_tc[ip->st.client_unit];
    if (!ts || size < 1 || size > 4 || first < 0 ||
        blob->count % ((size_t)size * ts) != 0) {
        interp_bad_value(ip, "@ArrayData with a bad size, type, first element or length");
        a->set = false;
        return;
    }
    a->set = true;
    a->first = (int32_t)first;
    a->size = (int32_t)size;
    a->type = type;
    a->data = blob->bytes;
    a->bytes = blob->count;
}

/* ---- Elements ---------------------------------------------------------------------- */

static uint32_t le32(const uint8_t *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

/* Component k of an element, as the number it holds (no normalisation). */
static double component(const uint8_t *p, GLenum type, int k)
{
    switch (type) {
    case GL_BYTE: return (int8_t)p[k];
    case GL_UNSIGNED_BYTE: return p[k];
    case GL_SHORT: return (int16_t)(uint16_t)(p[2 * k] | p[2 * k + 1] << 8);
    case GL_UNSIGNED_SHORT: return (uint16_t)(p[2 * k] | p[2 * k + 1] << 8);
    case GL_INT: return (int32_t)le32(p + 4 * k);
    case GL_UNSIGNED_INT: return le32(p + 4 * k);
    case GL_FLOAT: {
        uint32_t b = le32(p + 4 * k);
        float f;
        memcpy(&f, &b, sizeof f);
        return f;
    }
    default: { /* GL_DOUBLE */
        uint64_t b = (uint64_t)le32(p + 8 * k) | (uint64_t)le32(p + 8 * k + 4) << 32;
        double d;
        memcpy(&d, &b, sizeof d);
        return d;
    }
    }
}

/* GL 1.x table 2.9, as for glColor and glNormal with integer arguments. */
static double normalised(GLenum type, double c)
{
    switch (type) {
    case GL_UNSIGNED_BYTE: return c / 255.0;
    case GL_BYTE: return (2 * c + 1) / 255.0;
    case GL_UNSIGNED_SHORT: return c / 65535.0;
    case GL_SHORT: return (2 * c + 1) / 65535.0;
    case GL_UNSIGNED_INT: return c / 4294967295.0;
    case GL_INT: return (2 * c + 1) / 4294967295.0;
    default: return c;
    }
}

/* The element `index` of a recorded array, or NULL when the record does
 * not hold it. */
static const uint8_t *element(const struct interp_array_data *a, uint32_t index)
{
    if (!a->set || index < (uint32_t)a->first)
        return NULL;
    size_t es = (size_t)a->size * type_bytes(a->type);
    uint64_t at = (uint64_t)(index - (uint32_t)a->first) * es;
    if (at + es > a->bytes)
        return NULL;
    return a->data + at;
}

/* Whether every recorded array holds element `index`. */
static bool have_element(const interp *ip, uint32_t index)
{
    for (int k = 0; k < ARR_COUNT; k++)
        if (ip->arrays[k].set && !element(&ip->arrays[k], index))
            return false;
    for (int k = 1; k < INTERP_TEX_UNITS; k++)
        if (ip->unit_tc[k].set && !element(&ip->unit_tc[k], index))
            return false;
    return true;
}

/* glArrayElement(index), the arrays already checked to hold it. */
static void array_element(interp *ip, uint32_t index)
{
    gl_attribs *a = &ip->st.a;
    const struct interp_array_data *arr = ip->arrays;
    const uint8_t *p;
    if ((p = element(&arr[ARR_EDGEFLAG], index)))
        a->current.edge_flag = p[0] != 0;
    static const float def[4] = {0, 0, 0, 1};
    if ((p = element(&arr[ARR_TEXCOORD], index))) {
        for (int k = 0; k < 4; k++)
            a->current.texcoord[k] = k < arr[ARR_TEXCOORD].size
                                         ? (float)component(p, arr[ARR_TEXCOORD].type, k)
                                         : def[k];
    }
    for (int u = 1; u < INTERP_TEX_UNITS; u++) {
        const struct interp_array_data *t = &ip->unit_tc[u];
        if ((p = element(t, index)))
            for (int k = 0; k < 4; k++)
                ip->st.unit_texcoord[u][k] = k < t->size ? (float)component(p, t->type, k) : def[k];
    }
    if ((p = element(&arr[ARR_COLOR], index))) {
        GLenum t = arr[ARR_COLOR].type;
        for (int k = 0; k < 4; k++)
            a->current.color[k] =
                k < arr[ARR_COLOR].size ? (float)normalised(t, component(p, t, k)) : 1.0f;
        if (a->caps[INTERP_CAP_COLOR_MATERIAL])
            interp_cm_colour(ip);
    }
    /* GL 2.1 2.8: fog coordinates as they are, secondary colours
     * normalised as glSecondaryColor's (interp_fogsec.c draws them). */
    if ((p = element(&arr[ARR_FOGCOORD], index))) {
        double v = component(p, arr[ARR_FOGCOORD].type, 0);
        a->current.fog_coord = isfinite(v) ? (float)v : 0.0f;
    }
    if ((p = element(&arr[ARR_SECONDARY], index))) {
        GLenum t = arr[ARR_SECONDARY].type;
        for (int k = 0; k < 3 && k < arr[ARR_SECONDARY].size; k++)
            a->current.secondary[k] = (float)normalised(t, component(p, t, k));
    }
    if ((p = element(&arr[ARR_NORMAL], index))) {
        GLenum t = arr[ARR_NORMAL].type;
        for (int k = 0; k < 3; k++)
            a->current.normal[k] = (float)normalised(t, component(p, t, k));
    }
    if ((p = element(&arr[ARR_VERTEX], index)) && ip->in_begin && !ip->prim_skip) {
        double v[4] = {0, 0, 0, 1};
        for (int k = 0; k < arr[ARR_VERTEX].size; k++)
            v[k] = component(p, arr[ARR_VERTEX].type, k);
        interp_add_vertex(ip, v[0], v[1], v[2], v[3]);
    }
}

void interp_arrayelement(interp *ip, const rgl_cmd *cmd)
{
    int64_t i = cmd->arg[0].v.i;
    if (i < 0 || i > UINT32_MAX || !have_element(ip, (uint32_t)i)) {
        interp_diag(ip, DIAG_IGNORED, "glArrayElement: the trace holds no data for element %lld",
                    (long long)i);
        interp_arrays_forget(ip);
        return;
    }
    interp_unrec_use(ip, UNREC_USE_ARRAYS);
    array_element(ip, (uint32_t)i);
    interp_arrays_forget(ip);
}

/* ---- Draws -------------------------------------------------------------------------- */

/* Reads index i of an index array of type ub/us/ui. */
static uint32_t index_at(const uint8_t *p, size_t ts, size_t i)
{
    p += i * ts;
    return ts == 1 ? p[0] : ts == 2 ? (uint32_t)(p[0] | p[1] << 8) : le32(p);
}

static size_t index_bytes(GLenum type)
{
    return type == GL_UNSIGNED_BYTE ? 1 : type == GL_UNSIGNED_SHORT ? 2
         : type == GL_UNSIGNED_INT ? 4 : 0;
}

/* One draw: glBegin(mode), the elements (from `first` on, count of them,
 * or by the indices when idx is not NULL), glEnd. Every element is checked
 * against the recorded arrays first: a draw the trace cannot supply is
 * skipped whole. */
static void draw(interp *ip, GLenum mode, int64_t first, int64_t count, const uint8_t *idx,
                 size_t its)
{
    interp_unrec_use(ip, UNREC_USE_ARRAYS);
    /* Each element is checked, then drawn: it costs as a command does. */
    ip->cmds_run += (uint64_t)count;
    if (interp_budget_over(ip, ip->cmd ? ip->cmd->offset : 0))
        return;
    for (int64_t i = 0; i < count; i++) {
        uint64_t e = idx ? index_at(idx, its, (size_t)i) : (uint64_t)(first + i);
        if (e > UINT32_MAX || !have_element(ip, (uint32_t)e)) {
            interp_diag(ip, DIAG_IGNORED,
                        "vertex array draw: the trace holds no data for element %llu: draw "
                        "skipped", (unsigned long long)e);
            return;
        }
    }
    gl_attribs *a = &ip->st.a;
    float color[4], normal[3], texcoord[4];
    memcpy(color, a->current.color, sizeof color);
    memcpy(normal, a->current.normal, sizeof normal);
    memcpy(texcoord, a->current.texcoord, sizeof texcoord);
    bool edge_flag = a->current.edge_flag;
    gl_material mat[2] = {a->lighting.material[0], a->lighting.material[1]};
    float unit_tc[INTERP_TEX_UNITS][4];
    memcpy(unit_tc, ip->st.unit_texcoord, sizeof unit_tc);
    interp_prim_begin(ip, mode);
    ip->prim_indexed = idx != NULL;
    for (int64_t i = 0; i < count && !ip->cut; i++)
        array_element(ip, idx ? index_at(idx, its, (size_t)i) : (uint32_t)(first + i));
    interp_prim_end(ip);
    ip->prim_indexed = false;
    memcpy(a->current.color, color, sizeof color);
    memcpy(a->current.normal, normal, sizeof normal);
    memcpy(a->current.texcoord, texcoord, sizeof texcoord);
    a->current.edge_flag = edge_flag;
    a->lighting.material[0] = mat[0];
    a->lighting.material[1] = mat[1];
    memcpy(ip->st.unit_texcoord, unit_tc, sizeof unit_tc);
}

static bool check_mode(interp *ip, GLenum mode)
{
    if (mode > GL_POLYGON) {
        interp_bad_enum(ip, "primitive mode", mode);
        return false;
    }
    return true;
}

void interp_drawarrays(interp *ip, const rgl_cmd *cmd)
{
    GLenum mode = arg_enum(cmd, 0);
    int64_t first = cmd->arg[1].v.i, count = cmd->arg[2].v.i;
    if (check_mode(ip, mode)) {
        if (count < 0 || first < 0)
            interp_bad_value(ip, "glDrawArrays with a negative first or count");
        else
            draw(ip, mode, first, count, NULL, 0);
    }
    interp_arrays_forget(ip);
}

/* The indices of a glDrawElements-like command: false after a diagnostic. */
static bool indices_ok(interp *ip, int64_t count, GLenum type, const rgl_arg *blob, size_t *ts)
{
    *ts = index_bytes(type);
    if (!*ts) {
        interp_bad_enum(ip, "index type", type);
        return false;
    }
    if (count < 0) {
        interp_bad_value(ip, "negative index count");
        return false;
    }
    if ((uint64_t)blob->count != (uint64_t)count * *ts) {
        interp_bad_value(ip, "index data does not match the count and type");
        return false;
    }
    return true;
}

void interp_drawelements(interp *ip, const rgl_cmd *cmd)
{
    GLenum mode = arg_enum(cmd, 0), type = arg_enum(cmd, 2);
    int64_t count = cmd->arg[1].v.i;
    size_t ts;
    if (check_mode(ip, mode) && indices_ok(ip, count, type, &cmd->arg[3], &ts))
        draw(ip, mode, 0, count, cmd->arg[3].bytes, ts);
    interp_arrays_forget(ip);
}

/* glDrawRangeElements: start and end are a promise about the indices (GL
 * 1.2); indices outside them are undefined in GL and drawn here. */
void interp_drawrangeelements(interp *ip, const rgl_cmd *cmd)
{
    GLenum mode = arg_enum(cmd, 0), type = arg_enum(cmd, 4);
    uint64_t start = cmd->arg[1].v.u, end = cmd->arg[2].v.u;
    int64_t count = cmd->arg[3].v.i;
    size_t ts;
    if (check_mode(ip, mode)) {
        if (end < start)
            interp_bad_value(ip, "glDrawRangeElements with end < start");
        else if (indices_ok(ip, count, type, &cmd->arg[5], &ts))
            draw(ip, mode, 0, count, cmd->arg[5].bytes, ts);
    }
    interp_arrays_forget(ip);
}

/* ---- State the draws do not need (see the file comment) -------------------------------- */

void interp_vertexpointer(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }
void interp_normalpointer(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }
void interp_colorpointer(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }
void interp_texcoordpointer(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }
void interp_edgeflagpointer(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }
void interp_fogcoordpointer(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }
void interp_secondarycolorpointer(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }
void interp_interleavedarrays(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }
void interp_enableclientstate(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }
void interp_disableclientstate(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }

/* ---- Multi-draws (GL 1.4): a glDrawArrays / glDrawElements per entry ------------------- */

static bool multi_counts(interp *ip, const rgl_arg *blob, int64_t drawcount)
{
    if (drawcount < 0) {
        interp_bad_value(ip, "negative draw count");
        return false;
    }
    if ((uint64_t)blob->count != (uint64_t)drawcount * 4) {
        interp_bad_value(ip, "multi-draw arrays do not match the draw count");
        return false;
    }
    return true;
}

void interp_multidrawarrays(interp *ip, const rgl_cmd *cmd)
{
    GLenum mode = arg_enum(cmd, 0);
    const rgl_arg *first = &cmd->arg[1], *count = &cmd->arg[2];
    int64_t n = cmd->arg[3].v.i;
    if (check_mode(ip, mode) && multi_counts(ip, first, n) && multi_counts(ip, count, n)) {
        for (int64_t i = 0; i < n; i++) {
            int32_t f = (int32_t)le32(first->bytes + 4 * i), c = (int32_t)le32(count->bytes + 4 * i);
            if (f < 0 || c < 0) {
                interp_bad_value(ip, "glMultiDrawArrays with a negative first or count");
                break;
            }
            draw(ip, mode, f, c, NULL, 0);
        }
    }
    interp_arrays_forget(ip);
}

/* The indices of all the draws follow each other in one blob. */
void interp_multidrawelements(interp *ip, const rgl_cmd *cmd)
{
    GLenum mode = arg_enum(cmd, 0), type = arg_enum(cmd, 2);
    const rgl_arg *count = &cmd->arg[1], *indices = &cmd->arg[3];
    int64_t n = cmd->arg[4].v.i;
    size_t ts = index_bytes(type);
    if (!ts)
        interp_bad_enum(ip, "index type", type);
    else if (check_mode(ip, mode) && multi_counts(ip, count, n)) {
        uint64_t total = 0;
        for (int64_t i = 0; i < n; i++)
            total += le32(count->bytes + 4 * i) & 0x7fffffffu;
        bool neg = false;
        for (int64_t i = 0; i < n; i++)
            neg |= (int32_t)le32(count->bytes + 4 * i) < 0;
        if (neg || total * ts != indices->count) {
            interp_bad_value(ip, "glMultiDrawElements indices do not match the counts");
        } else {
            const uint8_t *p = indices->bytes;
            for (int64_t i = 0; i < n; i++) {
                uint32_t c = le32(count->bytes + 4 * i);
                draw(ip, mode, 0, c, p, ts);
                p += (size_t)c * ts;
            }
        }
    }
    interp_arrays_forget(ip);
}

/* ---- Buffer objects ----------------------------------------------------------------------- */

/* The recorder copies every buffer's contents into the trace (glBufferData,
 * glBufferSubData, glUnmapBuffer) and also resolves each draw's elements
 * from them (the file comment): the draws need nothing from these calls,
 * which are kept for dumps and tools. */
void interp_genbuffers(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }
void interp_deletebuffers(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }
void interp_bindbuffer(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }
void interp_bufferdata(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }
void interp_buffersubdata(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }
void interp_mapbuffer(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }
void interp_unmapbuffer(interp *ip, const rgl_cmd *cmd) { (void)ip; (void)cmd; }
