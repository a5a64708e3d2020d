/* fuzzgen.h: structure-aware generation and mutation of RayGL traces.
 *
 * The fuzz targets' custom mutator (fuzzgen_libfuzzer.c) and the suite's
 * fuzzgen test use it. An input is read as a trace (or as bare command bytes),
 * held as resources and frames of decoded commands, changed at the command
 * level with rows and argument values taken from format/commands.def,
 * enums.def and pnames.def, and written back as a whole valid trace with
 * rgl_trace_builder, so every checksum holds. Deterministic: the same input
 * and seed give the same output. Not thread-safe (static scratch space).
 */
#ifndef RGL_FUZZGEN_H
#define RGL_FUZZGEN_H

#include <stddef.h>
#include <stdint.h>

/* A byte-level mutator in libFuzzer's LLVMFuzzerMutate shape, or NULL. */
typedef size_t (*fuzzgen_bytes_fn)(uint8_t *data, size_t size, size_t max_size);

/* Writes a new trace of at most max_size bytes into out, built from table
 * rows (primitives, lists calling lists, arrays, textures, shapes, several
 * frames with carried state). Returns its size, 0 when none fits. */
size_t fuzzgen_generate(uint8_t *out, size_t max_size, uint32_t seed);

/* Mutates data[0..size) in place into at most max_size bytes and returns the
 * new size (libFuzzer's LLVMFuzzerCustomMutator contract). bytes, when
 * given, is used now and then on one command sequence (framing kept) or on
 * the whole input. */
size_t fuzzgen_mutate(uint8_t *data, size_t size, size_t max_size, uint32_t seed,
                      fuzzgen_bytes_fn bytes);

/* Combines two inputs into out (LLVMFuzzerCustomCrossOver's contract):
 * commands of the second spliced into the first, or its frames and
 * resources added. Returns the size written, 0 for none. */
size_t fuzzgen_crossover(const uint8_t *a, size_t asize, const uint8_t *b, size_t bsize,
                         uint8_t *out, size_t max_size, uint32_t seed);

#endif
