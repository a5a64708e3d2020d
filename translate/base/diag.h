/* diag.h: diagnostics collected while translating, printed by the CLI.
 *
 * The interpreter does not print: it records each diagnostic in a log, by
 * kind. A log keeps the first DIAG_KEEP messages of each kind and a count,
 * so a trace with a million bad calls costs a million increments, not a
 * million lines. Workers keep one log per frame; the CLI merges the logs in
 * frame order, so the output does not depend on -j.
 *
 * A note is said where its approximation can change a pixel of the frame;
 * where it cannot (the draws it concerns do not overlap, say), it is held:
 * kept and counted apart, marked, and printed only with --verbose (nothing
 * said in vain, docs/mapping.md "Notes").
 */
#ifndef RGL_DIAG_H
#define RGL_DIAG_H

#include <stdbool.h>
#include <stdint.h>

#define DIAG_KEEP 3   /* messages kept per kind and log */
/* Longest message kept, with its NUL: every note whole after a prefix, held
 * notes with their reason (diag.c checks it at compile time). A longer
 * message, which only a hostile trace's text can make, is not kept cut: it
 * is left out whole and counted in `dropped`. */
#define DIAG_TEXT 768
#define DIAG_PREFIX 192 /* "frame N, label, cmd N (glName) @0xN", with its NUL */
#define DIAG_WHY 160    /* longest reason a held note gives, with its NUL */
#define DIAG_HELD_MARK " (cannot change a pixel of this frame: "

/* Kinds. The GL_* ones are calls GL rejects (and the interpreter skips);
 * the NOTE_* ones are said once per run: state that is not translated (yet)
 * or only approximated. */
#define DIAG_KINDS(X) \
    X(GL_INVALID_ENUM, "invalid enum") \
    X(GL_INVALID_VALUE, "invalid value") \
    X(GL_INVALID_OPERATION, "invalid operation") \
    X(GL_STACK_OVERFLOW, "stack overflow") \
    X(GL_STACK_UNDERFLOW, "stack underflow") \
    X(IGNORED, "ignored call") \
    X(BAD_NUMBER, "NaN or infinite value") \
    X(LIMIT, "limit exceeded") \
    X(NOTE_LIGHTING, "approximated: the lights changed between lit draws of a frame more than 256 times (later draws are lit by the 256th set of lights)") \
    X(NOTE_FOG, "approximated: the fog changed between fogged draws of a frame (the first fogged draw's fog is used)") \
    X(NOTE_BLEND, "approximated: blending with colour or destination-alpha factors, or of lit or textured surfaces, other than GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA is drawn as that one") \
    X(NOTE_BLEND_ADD, "approximated: additive blending (all of the colour behind kept) keeps 127/128 of it") \
    X(NOTE_BLEND_EQUATION, "approximated: blend equations other than GL_FUNC_ADD (glBlendEquation) are drawn as GL_FUNC_ADD") \
    X(NOTE_ALPHA_TEST, "approximated: alpha test of lines and points (drawn whole), of faces whose vertex alphas lie on both sides of the reference (drawn whole), of a texture with vertex alphas that vary (the first vertex's alpha) or with GL_EQUAL or GL_NOTEQUAL and GL_LINEAR filtering (the texels tested one by one)") \
    X(NOTE_TEXTURE, "approximated: texture environment GL_COMBINE drawn as GL_MODULATE (a cube map's GL_DECAL, GL_BLEND and GL_ADD too), GL_BLEND and GL_ADD drawn opaque") \
    X(NOTE_TEX_SAMPLING, "approximated: a texture whose minification filter (without mipmaps) differs from its magnification filter is sampled with the magnification filter") \
    X(NOTE_TEX_CLAMP_BORDER, "approximated: GL_CLAMP with linear filtering: the edge texels' outer half, which OpenGL blends with the border colour, drawn as the edge texels") \
    X(NOTE_TEX_MIPMAP, "approximated: mipmapped textures take GL's level of detail per pixel on flat runs of faces only: one level per group of faces on curved meshes, the base level in display-list copies and with two texture units, level 0 of cube maps and 3D textures") \
    X(NOTE_LISTS, "not translated yet: display lists (calls skipped)") \
    X(NOTE_ARRAYS, "not translated yet: vertex arrays (draws skipped)") \
    X(NOTE_QUADRICS, "not translated yet: GLU quadrics (skipped)") \
    X(NOTE_STIPPLE, "approximated: stippled outlines of polygons (glPolygonMode GL_LINE): the pattern restarts at each polygon, where OpenGL restarts it at each triangle it cuts the polygon into") \
    X(NOTE_SCISSOR, "not translated: scissor test of geometry (drawn whole)") \
    X(NOTE_SCISSOR_CLEAR, "approximated: a scissored clear does not erase what was drawn before it inside its box") \
    X(NOTE_CLIP_PLANE, "not translated: user clip planes") \
    X(NOTE_STENCIL, "approximated: stencil buffer contents the scene does not follow (values other than one written over the cleared buffer by filled triangles; glStencilOp fail and zfail operations): drawn as if the test passed") \
    X(NOTE_COLOR_MASK, "not translated: colour mask and logic op") \
    X(NOTE_DEPTH, "approximated: draws without a depth test, with depth writes off (glDepthMask) or with a depth function other than GL_LESS or GL_LEQUAL overlap others on screen: the nearer shows where OpenGL shows the later or tests otherwise (draws in one plane show in draw order; where parts of one strip or fan overlap in one plane, either may show)") \
    X(NOTE_PROJECTION, "approximated: lit, fogged or depth-tested textured geometry drawn with another projection or viewport than the frame's camera is lit, fogged and textured as seen from that camera") \
    X(NOTE_CAMERA, "approximated: projection matrix is not a camera POV-Ray can express (default camera used)") \
    X(NOTE_PROJECTIVE_MODELVIEW, "approximated: projective modelview applied to the vertices") \
    X(NOTE_SPOT_SPECULAR, "approximated with --no-shadows: a spot light whose specular colour differs from its diffuse colour makes highlights as if they were equal") \
    X(NOTE_NORMALS, "approximated: lit normals that are not unit length in eye space (GL_NORMALIZE off) are used normalised") \
    X(NOTE_RENDER_MODE, "left out, as GL draws no pixel of it: geometry drawn in GL_SELECT or GL_FEEDBACK render mode") \
    X(NOTE_EVAL_INDEX, "not translated: colour-index evaluator maps (GL_MAP1_INDEX, GL_MAP2_INDEX)") \
    X(NOTE_PIXELS_DEPTH, "approximated: bitmaps and pixel rectangles show in front of the whole scene (drawn with the depth test on, or before later geometry)") \
    X(NOTE_PIXELS_OTHER, "not translated: depth and stencil pixels, and colour indices of type GL_BITMAP (glDrawPixels, glCopyPixels)") \
    X(NOTE_ACCUM_PASSES, "approximated: accumulation-buffer passes that differ other than by a sub-pixel jitter of the projection or an eye moved around a focal point (motion blur) are drawn as their first pass alone") \
    X(NOTE_FOG_COORD, "not translated yet: fog coordinates (GL_FOG_COORD_SRC GL_FOG_COORD) varying over a lit or textured surface: fogged by the eye distance") \
    X(NOTE_FOG_COORD_VERTEX, "approximated: fog coordinates under GL_EXP or GL_EXP2 fog, flat shading, or outside GL_FOG_START..GL_FOG_END: the fog factor is taken at the vertices (per face when flat) where GL interpolates the coordinate; exact where a primitive's fog coordinates are equal") \
    X(NOTE_FOG_LINES, "approximated: fog on lines: the fog factor is taken at the line's ends (exact for GL_LINEAR within GL_FOG_START..GL_FOG_END and unmapped blending)") \
    X(NOTE_COLOR_SUM, "not translated yet: the secondary colour of unlit textured surfaces (GL_COLOR_SUM): not added") \
    X(NOTE_SINGLE_COLOR, "approximated: lit textured surfaces with GL_SINGLE_COLOR get the highlight after the texture (as GL_SEPARATE_SPECULAR_COLOR), where GL modulates it by the texture") \
    X(NOTE_ACCUM_WEIGHTS, "approximated: accumulation weights that do not add up to one, GL_MULT or GL_ADD, are drawn as an average of the passes") \
    X(NOTE_MULTITEX, "approximated: texture units past the second enabled one not drawn; a unit after the first combined with one fragment colour (unlit, the first vertex's) unless both units use GL_MODULATE or the first replaces the colour; two units blended are drawn opaque") \
    X(NOTE_TEX_MODULATE_CM, "approximated: a lit GL_MODULATE texture whose diffuse colour comes from GL_COLOR_MATERIAL and varies over a mesh, blended, mipmapped, two-sided or on two units, is multiplied by the mean of that colour's channels") \
    X(NOTE_NURBS_TRIM, "approximated: GLU NURBS trim edges not along the u or v axis cut along the sampling grid") \
    X(NOTE_NURBS_OUTLINE, "approximated: GLU_OUTLINE_POLYGON of trimmed NURBS: the translator's grid, not GLU's triangles") \
    X(NOTE_NURBS_SAMPLING, "approximated: GLU NURBS sampled at 16+ steps a knot span, finer than GLU may sample them") \
    X(NOTE_NURBS_TESSELLATOR, "as recorded: GLU NURBS in GLU_NURBS_TESSELLATOR mode, drawn by the program's callbacks") \
    X(NOTE_MATERIAL_VERTEX, "approximated: glMaterial between the vertices of a primitive varying the shininess or two colours: drawn with the last vertex's material") \
    X(NOTE_GOURAUD, "approximated: lit faces large against their distance to a point light or local viewer, lit per pixel where OpenGL lights their corners (see --vertex-lighting)") \
    X(NOTE_SHADOW_HIGHLIGHT, "approximated with shadows: highlights of lights whose specular is not one multiple of their diffuse colour") \
    X(NOTE_POINT_FADE, "not translated: the point fade threshold (GL_POINT_FADE_THRESHOLD_SIZE; GL fades points only when multisampling)") \
    X(NOTE_TEX_MIRROR_CLAMP, "approximated: mirror-clamp texture wraps (GL_MIRROR_CLAMP_EXT and its kin) drawn as the image mirrored once, then clamped to its edge texels") \
    X(NOTE_TEX_3D, "approximated: 3D textures drawn as the slice (GL_NEAREST) or the blend of two slices (GL_LINEAR) that r picks where r is constant over a primitive; untextured where it varies") \
    X(NOTE_FRONT_BUFFER, "approximated: a single-buffered frame shows the drawing of at most 64 earlier frames since the last colour clear (the front buffer holds all of it)") \
    X(NOTE_POLYGON_OFFSET, "approximated: glPolygonOffset moves an offset polygon one pixel's width along the camera's rays (away from the eye for a positive offset), not by GL's window-depth offset; offset GLU and GLUT shapes are drawn as GL's facets") \
    X(NOTE_DEPTH_ONLY, "approximated: draws with every colour channel masked (glColorMask) are left out, but they wrote depth, which hides in GL what is drawn behind them later") \
    X(NOTE_FOG_BEHIND, "approximated: fogged primitives reaching behind the eye, which OpenGL fogs by |eye z| interpolated across the near-plane cut (denser near the eye than their distance)") \
    X(NOTE_RELIT_SPECULAR, "approximated: textured faces under GL_SEPARATE_SPECULAR_COLOR with a highlight, lit past white or showing their back under one-sided lighting, lit per pixel (unclamped, normals toward the viewer)") \
    X(NOTE_LOGIC_OP, "approximated: logic ops (glLogicOp) that read the colour buffer, of draws over anything but the clear colour, that cover a pixel twice or vary in colour over a face, or of lit, textured or fogged draws, are drawn as GL_COPY") \
    X(NOTE_BLEND_DEST, "approximated: blending whose result OpenGL takes from the colour behind in a way transmit and filter cannot show (GL_MIN, GL_MAX, GL_FUNC_SUBTRACT and GL_FUNC_REVERSE_SUBTRACT over a colour, destination factors, channel factors such as GL_CONSTANT_COLOR) is drawn as GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA except over the clear colour") \
    X(NOTE_DEPTH_CLEAR, "approximated: a depth-buffer clear (glClear GL_DEPTH_BUFFER_BIT, scissored or not) between draws that overlap on screen: later draws behind earlier ones stay hidden, where OpenGL draws them over") \
    X(NOTE_ACCUM_CLEAR, "approximated: the accumulation buffer's clear value other than zero (glClearAccum), accumulation clears and operations cut by the scissor box, and passes onto a buffer the frame did not clear: the returned passes are drawn as if accumulated onto zero over the whole window") \
    X(NOTE_POINT_TEXTURE, "not translated: textured smooth points without GL_POINT_SPRITE (drawn untextured discs)") \
    X(NOTE_TEX_LINES, "not translated: textured lines (drawn untextured)") \
    X(NOTE_PIXELS_MAP_COLOR, "approximated: glPixelTransfer colour maps (GL_MAP_COLOR) of pixel rectangles, and scales and biases of colour-index ones, are applied once, as GL says; Mesa applies them twice in some programs") \
    X(NOTE_TEX_COMPARE, "not translated: depth-texture comparison (GL_TEXTURE_COMPARE_MODE) where r varies over a primitive or the texture is mipmapped: the depth values drawn instead") \
    X(NOTE_COLOR_MATERIAL_BEGIN, "approximated: a glColor between glBegin and glEnd of the first draw after a glEnable(GL_COLOR_MATERIAL) that kept a glMaterial colour (as Mesa keeps it): the primitive's vertices before it take that material, where Mesa takes the colour current then") \
    X(NOTE_STENCIL_TWO_SIDE, "approximated: two-sided stencil (glStencilFuncSeparate, glStencilOpSeparate, glStencilMaskSeparate) testing or writing the front and back faces of one draw differently: the whole draw takes the front faces' stencil state") \
    X(NOTE_DRAW_BUFFER_DEPTH, "approximated: draws into a colour buffer the frame does not show (glDrawBuffer) are left out, but they wrote depth, which hides in GL what is drawn behind them later") \
    X(NOTE_LIT_OUTLINE, "approximated: lit faces outlined (glPolygonMode GL_LINE or GL_POINT) under two-sided lighting take their material's colour unlit, where OpenGL draws them in their vertices' lit colours") \
    X(NOTE_QUALITY, "approximated with --quality below 6: POV-Ray computes no image maps or transmitted light there: textured surfaces show their texture's mean colour, translucent ones and translucent bitmap or pixel-rectangle pixels hide what is behind them") \
    X(NOTE_GLTF_BLEND_ADD, "approximated in glTF: additive blending (all of the colour behind kept), which glTF's alpha blending cannot do, is written with an opacity of 1/128: what it adds nearly vanishes") \
    X(NOTE_CLEAR_COLOR_MASK, "approximated: a colour clear under a partial glColorMask clears every channel, where OpenGL keeps the masked channels of what was drawn before it and of the background") \
    X(NOTE_GLTF_PIXELS, "left out of glTF: bitmaps and pixel rectangles (glBitmap, glDrawPixels, glCopyPixels), which a glTF file cannot hold")

typedef enum diag_kind {
#define DIAG_ENUM_(name, text) DIAG_##name,
    DIAG_KINDS(DIAG_ENUM_)
#undef DIAG_ENUM_
    DIAG_COUNT
} diag_kind;

#define DIAG_FIRST_NOTE DIAG_NOTE_LIGHTING

typedef struct diag_entry {
    uint64_t count;   /* held notes included */
    uint64_t dropped; /* counted, but too long to keep whole */
    uint64_t held;    /* notes that cannot change a pixel of their frame */
    uint32_t kept;
    uint32_t held_kept; /* bit m: text[m] is a held note */
    char text[DIAG_KEEP][DIAG_TEXT];
} diag_entry;

typedef struct diag_log {
    diag_entry e[DIAG_COUNT];
} diag_log;

/* Empties a log. */
void diag_clear(diag_log *log);

/* The short name of a kind ("invalid enum"), never NULL. */
const char *diag_kind_name(diag_kind kind);

/* True for the NOTE_* kinds (printed once per run, not per call). */
bool diag_is_note(diag_kind kind);

/* Counts one diagnostic of `kind`; keeps "prefix: message" when fewer than
 * DIAG_KEEP are kept and it fits whole in DIAG_TEXT (otherwise it is
 * counted in `dropped`, never kept cut). The message is formatted only
 * then. Never formats
 * floating-point numbers (their text would depend on the locale). */
#if defined(__GNUC__)
__attribute__((format(printf, 4, 5)))
#endif
void diag_add(diag_log *log, diag_kind kind, const char *prefix, const char *fmt, ...);

/* Counts one held note of `kind` (a NOTE_* kind whose approximation
 * cannot change a pixel of its frame) and keeps "prefix: text (cannot
 * change a pixel of this frame: why)" as diag_add keeps its message. */
void diag_add_held(diag_log *log, diag_kind kind, const char *prefix, const char *why);

/* Whether kept message m of e is a held note. */
static inline bool diag_is_held(const diag_entry *e, uint32_t m)
{
    return m < DIAG_KEEP && (e->held_kept >> m & 1u);
}

/* Counts one diagnostic of `kind` whose message did not fit whole. */
void diag_drop(diag_log *log, diag_kind kind);

/* Adds every count and kept message of src to dst (dst first). */
void diag_merge(diag_log *dst, const diag_log *src);

#endif
