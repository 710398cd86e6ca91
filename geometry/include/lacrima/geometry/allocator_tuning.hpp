#pragma once
// Process-wide tuning of glibc's malloc for lacrima's allocation pattern, called once at the start
// of a program (the lacrima command, the test executables).

namespace lacrima {

// A frame is built from mesh-sized buffers (the refined skin's 440k vertices are 5 MB a field)
// that are allocated, filled and freed many times over: the rig's posed meshes, subdivision,
// smoothing, the liquid's film, per frame and per simulated frame before it. With glibc's
// defaults the heap gives freed memory at its top back to the kernel and grows again by what each
// request lacks, so every pass pays a page fault and a zero-fill per 4 KiB once more: on a
// one-frame render of the default shot (frame 46 at 160x90) 10 s of its 28 s were the kernel's.
// Here blocks up to 32 MiB come from the heap (M_MMAP_THRESHOLD; glibc mmaps them from 128 KiB
// up and unmaps them when freed), and the heap keeps up to 1 GiB of freed memory mapped at its top
// (M_TOP_PAD) instead of trimming it. `lacrima render` and `export` hand the free pages back after
// each frame (malloc_trim, docs/hardening.md "Memory over a sequence"), so a sequence's resident
// memory stays flat. Does nothing where malloc is not glibc's (the sanitizers bring their own).
void keepFreedMemoryForReuse();

}  // namespace lacrima
