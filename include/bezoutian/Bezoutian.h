// Compatibility path: the header lives in the elimination stage (doc/design.md, "Layout").
#ifndef BEZOUTIAN_FORWARD_BEZOUTIAN_H
#define BEZOUTIAN_FORWARD_BEZOUTIAN_H
#include <bezoutian/elimination/Bezoutian.h>
#endif
