// Compatibility path: the header lives in the algebraic stage (doc/design.md, "Layout").
#ifndef BEZOUTIAN_FORWARD_ALGEBRAIC_REAL_H
#define BEZOUTIAN_FORWARD_ALGEBRAIC_REAL_H
#include <bezoutian/algebraic/Algebraic_real.h>
#endif
