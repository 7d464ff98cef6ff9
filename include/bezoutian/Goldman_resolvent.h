// Compatibility path: the header lives in the elimination stage (doc/design.md, "Layout").
#ifndef BEZOUTIAN_FORWARD_GOLDMAN_RESOLVENT_H
#define BEZOUTIAN_FORWARD_GOLDMAN_RESOLVENT_H
#include <bezoutian/elimination/Goldman_resolvent.h>
#endif
