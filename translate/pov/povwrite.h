/* povwrite.h: the POV-Ray 3.7 backend: scene model -> SDL, and the .ini.
 *
 * One backend among possible others: it reads only the scene model
 * (scene.h) and writes text into an outbuf. docs/mapping.md explains every
 * mapping. The output never depends on the locale, holds no NaN or
 * infinity, no #fopen/#write and no #include but the user's own
 * (--include, pov_writer.c), and every string from the trace is escaped;
 * the same scene gives the same bytes. pov_writer.c makes it the driver's
 * writer "pov" (writer.h).
 */
#ifndef RGL_POVWRITE_H
#define RGL_POVWRITE_H

#include <stdint.h>

#include "outbuf.h"
#include "scene.h"

/* Where a frame came from, for the header comment. Strings may be NULL;
 * they are escaped before they reach the file. */
typedef struct pov_frame_info {
    const char *file_name; /* the .pov file's own name */
    const char *source;    /* the trace's name */
    uint64_t frame_index;  /* in file order */
    uint32_t stream, number;
    const char *frame_name; /* rayglFrameBegin's name, or NULL */
    /* Why the scene is incomplete (the frame cut by its budget, parts
     * that damage took), one reason a line, or NULL: each line becomes an
     * "// Incomplete: ..." comment under the header. */
    const char *incomplete;
} pov_frame_info;

typedef struct povwriter povwriter;

/* A writer with its reusable working memory; NULL on allocation failure.
 * One per thread. */
povwriter *povwriter_create(void);
void povwriter_destroy(povwriter *w);

/* Writes the scene as a complete SDL file. Returns 0, or -1 when memory ran
 * out or the sink failed (ob->failed). */
int povwriter_scene(povwriter *w, outbuf *ob, const scene *s, const pov_frame_info *info);

/* The texture images the last povwriter_scene referred to (file names
 * bare, to be written into the scene's folder; pngout.h), or NULL past
 * the last. */
typedef struct povtex_image povtex_image;
const povtex_image *povwriter_image(const povwriter *w, size_t i);

/* Writes those images into dir/textures (POVTEX_DIR, made when missing;
 * existing images are kept: pngout.h). Returns 0, or -1 with errno set
 * and failed (cap bytes) naming the image or the folder that could not be
 * written (pov_writer.c). */
int povwriter_write_images(const povwriter *w, const char *dir, char *failed, size_t cap);

/* Writes the .ini that renders the scene: `povray DIR/NAME.ini` run from
 * the directory raygl2pov ran in (POV-Ray resolves INI paths against the
 * current directory). dir is the output folder as the user gave it;
 * pov_file and png_file are bare file names inside it. Returns 0, or -1
 * when a path cannot be written into an INI (a double quote or a control
 * character in it) or the sink failed. */
int pov_write_ini(outbuf *ob, const scene *s, const char *dir, const char *pov_file,
                  const char *png_file);

/* True when pov_write_ini can express this folder name. */
bool pov_ini_path_ok(const char *dir);

/* The file every .ini of a folder reads first (Include_Header): POV-Ray
 * resolves an INI's paths against the current folder only, so from any
 * other folder than the one raygl2pov ran in (the output folder itself,
 * say) the render would fail with "Cannot create render state output
 * file". This header stops the parse first with a message saying where
 * to run it from. raygl-render, which passes its own library path and
 * output name, declares POV_RENDER_DECLARE to skip the check. */
#define POV_FOLDER_CHECK "raygl-folder.inc"
#define POV_RENDER_DECLARE "raygl_render"

/* Writes POV_FOLDER_CHECK's text for output folder dir (as the user gave
 * it, pov_ini_path_ok). Returns 0, or -1 when the sink failed. */
int pov_write_folder_check(outbuf *ob, const char *dir);

#endif
