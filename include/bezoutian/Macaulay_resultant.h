// Compatibility path: the header lives in the elimination stage (doc/design.md, "Layout").
#ifndef BEZOUTIAN_FORWARD_MACAULAY_RESULTANT_H
#define BEZOUTIAN_FORWARD_MACAULAY_RESULTANT_H
#include <bezoutian/elimination/Macaulay_resultant.h>
#endif
