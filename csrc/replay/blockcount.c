/*
** blockcount.c -- the block hook gles.target hands to the unicorn emulator:
** adds each executed basic block's size in bytes to a counter (in ARM state
** every instruction is 4 bytes). A hook in C costs a few nanoseconds a
** block, where a Python one costs a microsecond. Host code, not target code.
*/
#include <stdint.h>

__attribute__((visibility("default")))
void gles_count_block(void *uc, uint64_t address, uint32_t size, void *user)
{
    (void)uc;
    (void)address;
    *(uint64_t *)user += size;
}
