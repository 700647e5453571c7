/*
 * The toolkit's one call outside POSIX, and only a hint.  A large table
 * probed at random (the cellsets of qtbalance and qtmesh) costs a TLB miss
 * on nearly every probe when it lies on 4 KB pages; on 2 MB pages most of
 * those misses go.  Linux honours the hint when transparent huge pages are
 * in "madvise" mode (its default); where MADV_HUGEPAGE is unknown this is
 * nothing.
 */
#define _DEFAULT_SOURCE
#include <stdint.h>
#include <sys/mman.h>
#include <unistd.h>

#include "qtree.h"

#define HUGEPAGE	((size_t)2 << 20)

void
hugepage_hint(void *p, size_t n)
{
#ifdef MADV_HUGEPAGE
	long size = sysconf(_SC_PAGESIZE);
	uintptr_t page = size > 0 ? (uintptr_t)size : 1;
	uintptr_t from = ((uintptr_t)p + page - 1) & ~(page - 1);
	uintptr_t to = ((uintptr_t)p + n) & ~(page - 1);

	if (size > 0 && n >= HUGEPAGE && to > from)
		(void)madvise((void *)from, to - from, MADV_HUGEPAGE);
#else
	(void)p;
	(void)n;
#endif
}
