// Compatibility path: the header lives in the arrangement stage (doc/design.md, "Layout").
#ifndef BEZOUTIAN_FORWARD_ALGEBRAIC_KERNEL_INTEROP_H
#define BEZOUTIAN_FORWARD_ALGEBRAIC_KERNEL_INTEROP_H
#include <bezoutian/arrangement/Algebraic_kernel_interop.h>
#endif
