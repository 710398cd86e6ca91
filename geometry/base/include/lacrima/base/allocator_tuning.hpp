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
// (M_TOP_PAD) instead of trimming it. The price is fragmentation: over a sequence the resident
// memory creeps up (1-4 MiB in 24 frames of the RenderMemory test) while the memory in use stays
// flat, so `lacrima render` and `export` go over to returnFreedMemoryPromptly() after their first
// frame (which holds the shot's load and the simulation up to it, most of a short render's work).
// Does nothing where malloc is not glibc's (the sanitizers bring their own allocator).
void keepFreedMemoryForReuse();

// glibc's own thresholds back (mmap from 128 KiB, 128 KiB kept at the heap's top), held fixed: a
// big block goes back to the system when freed, so the frames of a sequence do not fragment the
// heap (docs/hardening.md, "Memory over a sequence").
void returnFreedMemoryPromptly();

}  // namespace lacrima
