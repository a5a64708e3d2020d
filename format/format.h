/* format.h: the RayGL trace format, shared by the recorder and the translator.
 *
 * Holds the command table's derived types (opcodes, argument descriptors),
 * the file and chunk layout constants, checksums, status codes, and the
 * decoder: a reader over a whole trace and an iterator over the commands of
 * one frame or resource. Bytes in, bytes out: no GL header, no printing, no
 * exit. docs/format.md is the specification this code follows.
 */
#ifndef RGL_FORMAT_H
#define RGL_FORMAT_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "cmdtable.h"

/* ---- Versions and limits ------------------------------------------------ */

#define RGL_FORMAT_MAJOR 1
#define RGL_FORMAT_MINOR 4

#define RGL_FILE_MAGIC "\x89RGL\r\n\x1a\n"
#define RGL_FILE_MAGIC_SIZE 8
#define RGL_FILE_HEADER_SIZE 32
#define RGL_SAMPLE_U32 0x0A0B0C0Du /* byte-order check */
#define RGL_SAMPLE_F32 0xC0C00000u /* -6.0f: float layout check */

#define RGL_CHUNK_SYNC "\xC3RGC"
#define RGL_CHUNK_HEADER_SIZE 16
#define RGL_CHUNK_TRAILER_SIZE 4
#define RGL_CHUNK_MAX_PAYLOAD (1u << 30)

#define RGL_OPCODE_LIMIT 0x4000u  /* opcodes are 1- or 2-byte varints */
#define RGL_MAX_ARGS 12           /* most arguments any row has */
#define RGL_ARRAY_MAX 64          /* most elements of an A() or N() argument */
#define RGL_STRING_MAX 4096       /* longest STR() argument */
#define RGL_RESOURCE_ID_MAX 0x7fffffffu

/* Chunk types. */
enum rgl_chunk_type {
    RGL_CHUNK_INFO = 1,     /* recorder and program description */
    RGL_CHUNK_RESOURCE = 2, /* a resource: command sequence or bytes */
    RGL_CHUNK_FRAME = 3,    /* one frame of one stream */
    RGL_CHUNK_INDEX = 4,    /* frame and resource offsets, written at close */
    RGL_CHUNK_END = 5,      /* fixed-size trailer pointing at the index */
};

/* Resource kinds. */
enum rgl_resource_kind {
    RGL_RES_COMMANDS = 1, /* a command sequence: state snapshot or list body */
    RGL_RES_BYTES = 2,    /* raw bytes: texel data */
};

/* Why a call was not recorded (@Skipped, format 1.3). */
enum rgl_skip_reason {
    RGL_SKIP_UNKNOWN_ENUM = 1, /* an enum the recorder does not know (GL may) */
    RGL_SKIP_NO_DATA = 2,      /* the data the call reads could not be read */
};

/* Frame flags. */
enum rgl_frame_flags {
    RGL_FRAME_LIVE_CONTEXT = 1u << 0, /* recorded with a live GL context */
    RGL_FRAME_STATE_CARRIED = 1u << 1, /* no snapshot: state continues from
                                          the stream's previous frame */
};

/* ---- Status codes -------------------------------------------------------- */

typedef enum rgl_status {
    RGL_OK = 0,
    RGL_END,            /* no more commands or chunks (not an error) */
    RGL_E_TRUNCATED,    /* input ends inside a value, command or chunk */
    RGL_E_MAGIC,        /* not a RayGL trace */
    RGL_E_VERSION,      /* a major version this reader does not know */
    RGL_E_BYTE_ORDER,   /* header sample values do not match */
    RGL_E_CHECKSUM,     /* a chunk header or payload fails its CRC */
    RGL_E_CHUNK,        /* a chunk header is malformed */
    RGL_E_OPCODE,       /* an opcode that is not in the table */
    RGL_E_VARINT,       /* a varint too long or too large for its type */
    RGL_E_LIMIT,        /* a count or length over its hard limit */
    RGL_E_RESOURCE,     /* a reference to a resource that is not there */
    RGL_E_NOMEM,        /* an allocation failed */
    RGL_E_IO,           /* a system call failed (errno is kept) */
    RGL_E_STATE,        /* a call that the current state does not allow */
    RGL_E_ARGUMENT,     /* a bad argument to a library function */
    RGL_E_IMAGE,        /* a snapshot image that does not decode as its
                           command describes it (format 1.2) */
    RGL_STATUS_COUNT
} rgl_status;

/* A constant English phrase for a status, never NULL. */
const char *rgl_status_str(rgl_status status);

/* Where and why decoding failed. offset is absolute in the file. */
typedef struct rgl_error {
    rgl_status status;
    uint64_t offset;
    uint64_t cmd_index; /* index of the command within its sequence */
    uint32_t opcode;    /* 0 when not inside a command */
    char detail[96];    /* short extra words, may be empty */
} rgl_error;

/* ---- The command table, derived ------------------------------------------ */

enum rgl_wire_type {
    RGL_T_b, RGL_T_ub, RGL_T_s, RGL_T_us, RGL_T_i, RGL_T_ui, RGL_T_f, RGL_T_d,
    RGL_T_e, RGL_T_bf, RGL_T_bo, RGL_T_sz, RGL_T_h, RGL_T_ip, RGL_T_COUNT
};

enum rgl_arg_kind {
    RGL_ARG_SCALAR,  /* P() */
    RGL_ARG_ARRAY,   /* A(): fixed count */
    RGL_ARG_COUNTED, /* N(): count on the wire */
    RGL_ARG_BLOB,    /* BLOB(): bytes */
    RGL_ARG_STRING,  /* STR(): bytes, no NUL */
};

enum rgl_api { RGL_API_GL, RGL_API_GLU, RGL_API_GLUT, RGL_API_RAY, RGL_API_REC };

typedef struct rgl_arg_desc {
    uint8_t kind;   /* enum rgl_arg_kind */
    uint8_t type;   /* enum rgl_wire_type */
    uint16_t count; /* elements of an ARRAY */
    const char *name;
} rgl_arg_desc;

typedef struct rgl_cmd_info {
    uint16_t opcode;
    uint8_t api;   /* enum rgl_api */
    uint8_t nargs;
    const char *name;    /* "glVertex3f", "gluSphere", "@Matrix" */
    const char *handler; /* interpreter handler name */
    const rgl_arg_desc *args;
} rgl_cmd_info;

enum rgl_opcode {
#define RGL_CMD(op, api, gen, name, handler, ...) RGL_OP_##name = op,
#include "commands.def"
#undef RGL_CMD
};

/* The row of an opcode, or NULL for an opcode not in the table. */
const rgl_cmd_info *rgl_cmd_info_get(uint32_t opcode);

/* Every row in table order; *count receives the number of rows. */
const rgl_cmd_info *const *rgl_cmd_info_all(size_t *count);

/* Number of values a GL parameter name takes (GL_AMBIENT: 4), 0 if unknown. */
uint32_t rgl_pname_count(uint32_t pname);

/* Values per control point of an evaluator map target (GL_MAP1_* or
 * GL_MAP2_*, GL 1.x table 5.1: GL_MAP1_VERTEX_4 has 4), 0 for any other
 * value; *two receives whether it is a GL_MAP2_* target (may be NULL). */
uint32_t rgl_map_components(uint32_t target, bool *two);

/* The calls that take a parameter name (format/pnames.def). */
enum rgl_pname_family {
    RGL_PN_LIGHT = 1u << 0,
    RGL_PN_MATERIAL = 1u << 1,
    RGL_PN_LIGHT_MODEL = 1u << 2,
    RGL_PN_FOG = 1u << 3,
    RGL_PN_TEX_PARAMETER = 1u << 4,
    RGL_PN_TEX_ENV = 1u << 5,
    RGL_PN_TEX_GEN = 1u << 6,
    RGL_PN_POINT_PARAMETER = 1u << 7,
};

/* Number of values the calls of `family` read for pname: 0 when pname is
 * unknown or not theirs (GL refuses it and reads nothing). */
uint32_t rgl_pname_count_in(uint32_t family, uint32_t pname);

/* The GL_ name of an enum value, or NULL. For values shared by several names
 * (GL_POINTS and GL_ZERO), `hint` picks the family: the argument's name. */
const char *rgl_enum_name(uint32_t value, const char *hint);

/* ---- Checksums and layout helpers (used by both sides) -------------------- */

/* CRC-32C (Castagnoli). Start with crc = 0; pass the result back in to
 * continue over more bytes. Uses the SSE4.2 instruction when the CPU has it.
 * Thread-safe. */
uint32_t rgl_crc32c(uint32_t crc, const void *data, size_t size);

/* The two implementations behind rgl_crc32c, for tests and benchmarks: the
 * portable one, and the SSE4.2 one (which falls back to the portable one when
 * the CPU lacks the instruction; rgl_crc32c_hw_available() tells). */
uint32_t rgl_crc32c_sw(uint32_t crc, const void *data, size_t size);
uint32_t rgl_crc32c_hw(uint32_t crc, const void *data, size_t size);
bool rgl_crc32c_hw_available(void);

/* Writes the 32-byte file header. */
void rgl_file_header_encode(uint8_t out[RGL_FILE_HEADER_SIZE], uint32_t flags);

/* Writes a 16-byte chunk header for a payload of `size` bytes. */
void rgl_chunk_header_encode(uint8_t out[RGL_CHUNK_HEADER_SIZE], uint8_t type, uint32_t size);

/* ---- Decoding one command sequence ---------------------------------------- */

typedef struct rgl_arg {
    uint8_t kind;   /* enum rgl_arg_kind */
    uint8_t type;   /* enum rgl_wire_type */
    uint32_t count; /* elements (ARRAY, COUNTED) or bytes (BLOB, STRING) */
    union {
        int64_t i;  /* signed types */
        uint64_t u; /* unsigned types, enums, handles */
        double f;   /* f, d */
    } v;            /* SCALAR */
    const double *array;   /* ARRAY, COUNTED: elements converted to double */
    const uint8_t *bytes;  /* BLOB, STRING: points into the input */
} rgl_arg;

typedef struct rgl_cmd {
    uint32_t opcode;
    const rgl_cmd_info *info;
    uint64_t offset; /* absolute file offset of the opcode */
    uint64_t index;  /* index in the sequence */
    uint32_t nargs;
    rgl_arg arg[RGL_MAX_ARGS];
    double scratch[2 * RGL_ARRAY_MAX]; /* storage for array elements */
} rgl_cmd;

typedef struct rgl_cmd_iter {
    const uint8_t *start, *pos, *end;
    uint64_t base_offset; /* file offset of start */
    uint64_t index;
    rgl_error error;
} rgl_cmd_iter;

/* Iterates over the commands in [data, data+size), which sits at file offset
 * base_offset (used only in errors). The data must outlive the iterator. */
void rgl_cmd_iter_init(rgl_cmd_iter *it, const uint8_t *data, size_t size, uint64_t base_offset);

/* Decodes the next command into *cmd. Returns RGL_OK, RGL_END at the end, or
 * an error (details in it->error); after an error the iterator stays at the
 * failing command and keeps returning the same error. Never allocates; every
 * count and length is checked against its limit and the bytes left first;
 * varints must be canonical (docs/format.md, section 1), so a decoded command
 * re-encodes (rgl_cmd_encode) to exactly its input bytes. */
rgl_status rgl_cmd_next(rgl_cmd_iter *it, rgl_cmd *cmd);

/* The wire size of a call (a GL, GLU, GLUT or RayGL command, not a
 * record) whose opcode is one byte and whose arguments are all float
 * scalars, one at least (glVertex3f, glNormal3f, glColor4f, ...): 1 + 4 per
 * argument; 0 for any other opcode. */
uint32_t rgl_cmd_float_size(uint32_t opcode);

/* Steps over the next command without decoding it when it is such a call
 * (rgl_cmd_float_size): for a scan that looks at the other commands only
 * (a float argument cannot be malformed, so rgl_cmd_next would read exactly
 * those bytes). Returns the opcode skipped, or 0 (nothing done: another
 * command, one cut short, the end, or an error) for the caller to take
 * rgl_cmd_next. */
uint32_t rgl_cmd_skip_floats(rgl_cmd_iter *it);

/* The same over a run: steps over every such call from the current one to
 * the first other command (or the end). Returns how many it stepped over,
 * 0 when rgl_cmd_skip_floats would do nothing. One call per run rather
 * than per command: a frame is mostly such runs (issue 16). */
size_t rgl_cmd_skip_float_run(rgl_cmd_iter *it);

/* A scalar (k = 0) or the k-th element of an array argument (or byte of a
 * blob or string), as double / int64; 0 when k is out of range. rgl_arg_i
 * truncates floating values toward zero, saturates at the int64 limits and
 * gives 0 for NaN. */
double rgl_arg_f(const rgl_arg *arg, uint32_t k);
int64_t rgl_arg_i(const rgl_arg *arg, uint32_t k);

/* ---- Reading a whole trace ------------------------------------------------ */

typedef struct rgl_frame_info {
    uint32_t stream;
    uint32_t number;    /* frame number within its stream, from 0 */
    uint32_t flags;     /* enum rgl_frame_flags */
    uint32_t state;     /* resource id of the state snapshot, 0 for none */
    uint64_t offset;    /* file offset of the chunk */
    const uint8_t *commands; /* the frame's command sequence */
    size_t commands_size;
    uint64_t commands_offset; /* file offset of commands[0] */
} rgl_frame_info;

typedef struct rgl_resource {
    uint32_t id;
    uint32_t kind; /* enum rgl_resource_kind */
    const uint8_t *data;
    size_t size;
    uint64_t data_offset; /* file offset of data[0] */
} rgl_resource;

typedef struct rgl_reader rgl_reader;

/* Opens a trace held in memory (borrowed: it must outlive the reader), or a
 * file (mapped read-only). Checks the header, then finds every chunk: through
 * the index when the file has a valid one, otherwise by a scan that skips
 * damaged regions and records each as a damage error. Returns NULL-free
 * status; on error *out is NULL and *err, if given, says where. */
rgl_status rgl_reader_open_memory(const uint8_t *data, size_t size, rgl_reader **out,
                                  rgl_error *err);
rgl_status rgl_reader_open_file(const char *path, rgl_reader **out, rgl_error *err);
void rgl_reader_destroy(rgl_reader *reader);

size_t rgl_reader_frame_count(const rgl_reader *reader);

/* Frame i (file order). Verifies the chunk's payload checksum first. */
rgl_status rgl_reader_frame(rgl_reader *reader, size_t i, rgl_frame_info *out, rgl_error *err);

/* The resource with this id, checksum verified. */
rgl_status rgl_reader_resource(rgl_reader *reader, uint32_t id, rgl_resource *out,
                               rgl_error *err);

/* Resources in id order (one per id): count, and the i-th, checksum verified.
 * For tools that list every resource (dumpers, fuzz targets). */
size_t rgl_reader_resource_count(const rgl_reader *reader);
rgl_status rgl_reader_resource_at(rgl_reader *reader, size_t i, rgl_resource *out,
                                  rgl_error *err);

/* Damaged regions found while opening: count, and the i-th as an error. At
 * most 1024 are listed; a file with more has the first 1024. */
size_t rgl_reader_damage_count(const rgl_reader *reader);
const rgl_error *rgl_reader_damage(const rgl_reader *reader, size_t i);

/* Whether the trace was closed: it ends with the END trailer the recorder
 * writes when it closes the file. A recording that was killed, or stopped
 * by a full disk, was not: *tail (when tail is not NULL) then receives the
 * offset of the chunk that the end of the file cuts short, or the file size
 * when the file ends between chunks (0 for a closed trace). Such a
 * cut-short last chunk is the recording's last write, not damage: it is not
 * listed by rgl_reader_damage. */
bool rgl_reader_closed(const rgl_reader *reader, uint64_t *tail);

/* The INFO chunk's text (key=value lines), or NULL. */
const char *rgl_reader_info(const rgl_reader *reader, size_t *size);

/* ---- Encoding from the decoded form (tools, tests, fuzz seeds) -------------- */

/* Sets cmd to the command `opcode` with its descriptors and zeroed arguments.
 * Returns RGL_E_OPCODE for an opcode not in the table. */
rgl_status rgl_cmd_init(rgl_cmd *cmd, uint32_t opcode);

/* Encodes cmd, as rgl_cmd_next() would have decoded it, into out. Returns the
 * bytes written, or 0 when cap is too small or an argument breaks its
 * descriptor (a count over its limit, a value out of its type's range). */
size_t rgl_cmd_encode(const rgl_cmd *cmd, uint8_t *out, size_t cap);

/* Builds a whole trace in memory: header, resources, frames, index, end. */
typedef struct rgl_trace_builder rgl_trace_builder;

rgl_trace_builder *rgl_trace_builder_create(void);
void rgl_trace_builder_destroy(rgl_trace_builder *builder);
/* Adds a resource chunk; *id receives its id (ids count up from 1). */
rgl_status rgl_trace_builder_resource(rgl_trace_builder *builder, uint32_t kind,
                                      const void *data, size_t size, uint32_t *id);
/* Adds an INFO chunk with the given text (key=value lines). */
rgl_status rgl_trace_builder_info(rgl_trace_builder *builder, const char *text, size_t size);
/* Adds a frame chunk whose command sequence is the given bytes. */
rgl_status rgl_trace_builder_frame(rgl_trace_builder *builder, uint32_t stream, uint32_t number,
                                   uint32_t flags, uint32_t state, const uint8_t *commands,
                                   size_t size);
/* Appends the index and end chunks (when with_index) and returns the bytes,
 * owned by the builder and valid until it is destroyed. Every builder call
 * fails with RGL_E_STATE after finish, and with the first error (RGL_E_NOMEM,
 * RGL_E_LIMIT) again after any failure: the builder is then sticky-failed. */
rgl_status rgl_trace_builder_finish(rgl_trace_builder *builder, bool with_index,
                                    const uint8_t **data, size_t *size);

/* ---- Frame snapshots (format 1.2, format/snapimage.c) ------------------------- */

#define RGL_SNAPSHOT_SIDE_MAX 16384    /* widest and tallest snapshot */
#define RGL_SNAPSHOT_FORMAT_RGB 0x1907 /* GL_RGB: 3 bytes a pixel */
#define RGL_SNAPSHOT_CODEC_ZLIB 1      /* a zlib stream (RFC 1950) */

/* An @Snapshot command's arguments, checked. */
typedef struct rgl_snapshot {
    int32_t x, y;          /* the viewport's corner the image was read at */
    int32_t width, height; /* 1 .. RGL_SNAPSHOT_SIDE_MAX */
    uint32_t format;       /* RGL_SNAPSHOT_FORMAT_RGB */
    uint32_t codec;        /* RGL_SNAPSHOT_CODEC_ZLIB */
    uint32_t image;        /* id of the BYTES resource holding the stream */
    uint64_t offset;       /* file offset of the command, for messages */
} rgl_snapshot;

/* Reads an @Snapshot command into *out. Returns RGL_OK, or RGL_E_IMAGE
 * (a size out of range, an unknown format or codec, no resource id) with
 * err naming the command, or RGL_E_ARGUMENT when cmd is not an @Snapshot. */
rgl_status rgl_snapshot_from_cmd(const rgl_cmd *cmd, rgl_snapshot *out, rgl_error *err);

/* Inflates the snapshot's image from its resource into a new buffer of
 * width * height * 3 bytes, top row first (*rgb; free it with
 * rgl_format_realloc(p, 0)). Checks before allocating that the compressed
 * size can hold the image at zlib's best ratio, and after inflating that the
 * stream ends exactly at the image's last byte and at the resource's end.
 * Errors: RGL_E_IMAGE (naming the offset in the resource where it failed),
 * RGL_E_RESOURCE (not a BYTES resource), RGL_E_NOMEM. */
rgl_status rgl_snapshot_decode(const rgl_snapshot *snap, const rgl_resource *res, uint8_t **rgb,
                               rgl_error *err);

/* Compresses width * height * 3 bytes of RGB (rows in the order given) into
 * a zlib stream at the given level (1 fastest .. 9 smallest). The stream is
 * written to a buffer from alloc (realloc semantics); *out and *size receive
 * it. Returns RGL_OK, RGL_E_NOMEM, or RGL_E_ARGUMENT for a size out of range.
 * Thread-safe; for the recorder (with its allocation wrapper) and tests. */
rgl_status rgl_snapshot_encode(const uint8_t *rgb, int32_t width, int32_t height, int level,
                               void *(*alloc)(void *ptr, size_t size), uint8_t **out,
                               size_t *size);

/* ---- Text dump ---------------------------------------------------------------- */

/* Formats one command as a GL call log line, without newline:
 *   glLightfv(light=GL_LIGHT0, pname=GL_POSITION, params=[1, 2, 3, 0])
 * Floats print with the fewest digits that read back to the same value; the
 * output never depends on the locale. Returns the length the full line needs
 * (like snprintf); out is always NUL-terminated when cap > 0. */
size_t rgl_cmd_format(const rgl_cmd *cmd, char *out, size_t cap);

/* ---- Allocation ----------------------------------------------------------------- */

/* Every allocation made under format/ (reader, builder) goes through this
 * wrapper: realloc semantics, and realloc(p, 0) frees p and returns NULL. */
void *rgl_format_realloc(void *ptr, size_t size);

/* Test hook: the n-th allocation from now (1 = the next) and every one after
 * it fail, until called again; n = 0 turns failures off. Not thread-safe. */
void rgl_format_fail_alloc(unsigned long n);

#endif
