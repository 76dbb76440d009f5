// glibc's allocator tuned for tensor work: freed blocks stay in the process for the next step instead of going
// back to the kernel and being faulted in, zeroed, again.
//
// By default glibc serves a block of more than 128 KiB (raised adaptively up to 32 MiB) with its own mmap and
// returns it with munmap on free, and trims the heap top past 128 KiB. A training step of MDM 4x256 at batch 64
// allocates and frees hundreds of activation tensors of 1-40 MiB, so each step paid page faults and page zeroing
// for all of them (the time it saved: bench/README.md, "Training step (issue 43)"), the losses equal to the bit.
// Costs: the process keeps up to about one step's peak of freed memory.
#pragma once

namespace t2imu {

// Sets glibc's mmap threshold to its maximum (32 MiB: smaller blocks come from the heap and are reused), turns
// off heap trimming below 2 GiB of free heap top and pads each heap growth by 1 GiB. No effect on other C libraries.
void keep_freed_memory_for_reuse();

}  // namespace t2imu
