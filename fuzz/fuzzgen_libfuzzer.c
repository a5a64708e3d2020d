/* fuzzgen_libfuzzer.c: libFuzzer's custom mutator hooks, for both targets.
 *
 * Linked only into the libFuzzer binaries (-Dfuzz=true): libFuzzer calls
 * these instead of its own mutator and crossover; fuzzgen mutates at the
 * command level and hands LLVMFuzzerMutate (libFuzzer's byte mutator) one
 * sequence or the whole input now and then. The seed is libFuzzer's, so a
 * run with -seed=N repeats.
 */
#include "fuzzgen.h"

size_t LLVMFuzzerMutate(uint8_t *data, size_t size, size_t max_size);
size_t LLVMFuzzerCustomMutator(uint8_t *data, size_t size, size_t max_size, unsigned int seed);
size_t LLVMFuzzerCustomCrossOver(const uint8_t *data1, size_t size1, const uint8_t *data2,
                                 size_t size2, uint8_t *out, size_t max_out_size,
                                 unsigned int seed);

size_t LLVMFuzzerCustomMutator(uint8_t *data, size_t size, size_t max_size, unsigned int seed)
{
    return fuzzgen_mutate(data, size, max_size, seed, LLVMFuzzerMutate);
}

size_t LLVMFuzzerCustomCrossOver(const uint8_t *data1, size_t size1, const uint8_t *data2,
                                 size_t size2, uint8_t *out, size_t max_out_size,
                                 unsigned int seed)
{
    return fuzzgen_crossover(data1, size1, data2, size2, out, max_out_size, seed);
}
