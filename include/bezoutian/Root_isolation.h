// Compatibility path: the header lives in the algebraic stage (doc/design.md, "Layout").
#ifndef BEZOUTIAN_FORWARD_ROOT_ISOLATION_H
#define BEZOUTIAN_FORWARD_ROOT_ISOLATION_H
#include <bezoutian/algebraic/Root_isolation.h>
#endif
