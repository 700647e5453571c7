/*
 * qtcatcopy.c: qtcat's shard files copied whole.  A file whose head is
 * the first input's byte for byte, and whose first and last cells say it
 * is one whole subtree, is probed here from its two ends; qtcat.c then
 * copies its bytes at the place of its first cell, counting their
 * newlines.
 */
#include <sys/mman.h>
#include <sys/stat.h>

#include <errno.h>
#include <fcntl.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "qtree.h"
#include "qtcat.h"

/* n bytes at off, all of them, or -1. */
ssize_t
readat(int fd, char *buf, size_t n, off_t off)
{
	size_t got = 0;
	ssize_t k;

	while (got < n) {
		if ((k = pread(fd, buf + got, n - got, off + (off_t)got)) < 0) {
			if (errno == EINTR)
				continue;
			return -1;
		}
		if (k == 0)
			break;
		got += (size_t)k;
	}
	return (ssize_t)got;
}

/* An unsigned decimal of at most 18 digits from s to end, or -1. */
static long long
decimal(const char *s, const char *end)
{
	long long v = 0;

	if (s == end || end - s > 18 || (*s == '0' && end - s > 1))
		return -1;
	for (; s < end; s++) {
		if (*s < '0' || *s > '9')
			return -1;
		v = 10 * v + (*s - '0');
	}
	return v;
}

/*
 * The cell of line s (n bytes, its newline excluded), for the merge's
 * order and checks: "node PATH LEVEL IX IY X Y SIZE" or "leaf ... CLASS",
 * in 3D "node PATH LEVEL IX IY IZ X Y Z SIZE" or "leaf ... CLASS", the
 * path, level, column, row (and layer) agreeing; its corner and size,
 * like every cell between, are copied as they are.  Returns -1 for
 * anything else, which the reader then reads.
 */
static int
blockcell(const char *s, size_t n, struct cell *c, char *path)
{
	const char *f[12], *e = s + n, *p = s;
	long long level, ix, iy, iz = 0;
	uint64_t px, py, pz = 0;
	int nf = 0, nn = dim == 3 ? 10 : 8;	/* a node's fields */

	while (p < e && nf < nn + 2) {
		f[nf++] = p;
		while (p < e && *p != ' ')
			p++;
		if (p < e)
			p++;
	}
	if (p != e || s[n - 1] == ' ')
		return -1;
	if (nf == nn && memcmp(s, "node ", 5) == 0)
		c->class = 0;
	else if (nf == nn + 1 && memcmp(s, "leaf ", 5) == 0 &&
	    e - f[nn] == 1 && strchr("FEP", *f[nn]) != NULL)
		c->class = *f[nn];
	else
		return -1;
	if ((level = decimal(f[2], f[3] - 1)) < 0 || level > QT_MAXLEVEL ||
	    (ix = decimal(f[3], f[4] - 1)) < 0 ||
	    (iy = decimal(f[4], f[5] - 1)) < 0 ||
	    (dim == 3 && (iz = decimal(f[5], f[6] - 1)) < 0) ||
	    f[2] - 1 - f[1] != (level > 0 ? level : 1))
		return -1;
	memcpy(path, f[1], f[2] - 1 - f[1]);
	path[f[2] - 1 - f[1]] = '\0';
	if ((dim == 3 ? pathcell3(path, (int)level, &px, &py, &pz) :
	    cell_frompath(path, (int)level, &px, &py)) < 0 ||
	    px != (uint64_t)ix || py != (uint64_t)iy || pz != (uint64_t)iz)
		return -1;
	if (level == 0)
		path[0] = '\0';
	c->path = level > 0 ? path : ".";
	c->level = (int)level;
	c->ix = px;
	c->iy = py;
	c->id = 0;
	c->frac = -1;
	c->text = NULL;
	c->textlen = 0;
	return 0;
}

/*
 * Whether input p, the file at path, is a shard to copy whole: a regular
 * file, one stream, the first head byte for byte, then cells from its
 * first to its last in preorder of one subtree (the last a leaf that ends
 * the subtree of the first), then the end record.  Else 0, and the reader
 * reads it.
 */
int
probe(struct input *p, const char *path)
{
	struct block b;
	struct stat st;
	char tail[512], *t, *nl, *end;
	size_t k, n;
	long long count;
	int fd;

	if (strcmp(path, "-") == 0 || (fd = open(path, O_RDONLY)) < 0)
		return 0;
	memset(&b, 0, sizeof(b));
	b.fd = fd;
	if (fstat(fd, &st) < 0 || !S_ISREG(st.st_mode) ||
	    st.st_size < (off_t)headlen + 16)
		goto no;
	/* the head, byte for byte */
	if (chunk == NULL)
		chunk = xmalloc(CHUNK);
	for (k = 0; k < headlen; k += n) {
		n = headlen - k < CHUNK ? headlen - k : CHUNK;
		if (readat(fd, chunk, n, (off_t)k) != (ssize_t)n ||
		    memcmp(chunk, headtext + k, n) != 0)
			goto no;
	}
	/* the first cell */
	n = (size_t)(st.st_size - (off_t)headlen) < sizeof(tail) ?
	    (size_t)(st.st_size - (off_t)headlen) : sizeof(tail);
	if (readat(fd, tail, n, (off_t)headlen) != (ssize_t)n ||
	    (nl = memchr(tail, '\n', n)) == NULL ||
	    blockcell(tail, nl - tail, &p->rec.c, b.firstpath) < 0)
		goto no;
	b.from = (off_t)headlen;
	b.firstlen = nl - tail + 1;
	/* the end record, and the last cell before it */
	n = (size_t)(st.st_size - b.from) < sizeof(tail) ?
	    (size_t)(st.st_size - b.from) : sizeof(tail);
	if (readat(fd, tail, n, st.st_size - (off_t)n) != (ssize_t)n ||
	    tail[n - 1] != '\n')
		goto no;
	end = tail + n - 1;
	for (t = end; t > tail && t[-1] != '\n'; t--)
		;
	if (t == tail || end - t < 5 || memcmp(t, "end ", 4) != 0 ||
	    (count = decimal(t + 4, end)) < 0 ||
	    (unsigned long long)count <= headrecs)
		goto no;
	b.ncells = (unsigned long long)count - headrecs;
	b.to = st.st_size - (off_t)(tail + n - t);
	for (nl = t - 1; nl > tail && nl[-1] != '\n'; nl--)
		;
	if (nl == tail && b.to - (off_t)(t - nl) != b.from)
		goto no;	/* the last cell's line is not all in tail */
	if (blockcell(nl, t - 1 - nl, &b.last, b.lastpath) < 0)
		goto no;
	/*
	 * One subtree, whole: a leaf alone, or a node and, last, the leaf
	 * 33...3 under it.
	 */
	if (p->rec.c.class != 0) {
		if (b.to - b.from != (off_t)b.firstlen)
			goto no;
	} else {
		if (b.last.class == 0 || b.last.level <= p->rec.c.level ||
		    memcmp(b.lastpath, b.firstpath, p->rec.c.level) != 0)
			goto no;
		for (k = p->rec.c.level; k < (size_t)b.last.level; k++)
			if (b.lastpath[k] != lastdigit)
				goto no;
	}
	p->b = xmalloc(sizeof(*p->b));
	*p->b = b;
	p->rec.c.path = p->b->firstpath[0] ? p->b->firstpath : ".";
	p->b->last.path = p->b->lastpath[0] ? p->b->lastpath : ".";
	p->rec.lineno = headlines + 1;
	return 1;
no:
	close(fd);
	return 0;
}

/*
 * The newlines of n bytes: sixteen counts a byte wide, one for each byte
 * of sixteen in turn, added up before any can pass 255 (a loop that
 * compilers make vector instructions of).
 */
unsigned long long
newlines(const char *s, size_t n)
{
	unsigned long long c = 0;
	unsigned char acc[16];
	size_t i = 0, r;
	int j;

	while (n - i >= 16) {
		memset(acc, 0, sizeof(acc));
		for (r = 0; r < 255 && n - i >= 16; r++, i += 16)
			for (j = 0; j < 16; j++)
				acc[j] += s[i + j] == '\n';
		for (j = 0; j < 16; j++)
			c += acc[j];
	}
	for (; i < n; i++)
		c += s[i] == '\n';
	return c;
}

/*
 * Copies the bytes of shard p from at, at most a window of them, mapped
 * (so that they are read in place, and not at all on their way to
 * /dev/null), else read; adds their newlines to *lines; returns how many.
 */
size_t
copyspan(struct input *p, off_t at, unsigned long long *lines)
{
	static long page;
	struct block *b = p->b;
	struct stat st;
	off_t base;
	size_t n, len;
	ssize_t k;
	char *m;

	if (page == 0 && (page = sysconf(_SC_PAGESIZE)) <= 0)
		page = -1;
	/* a mapping past the end of a file cut short would kill qtcat */
	if (fstat(b->fd, &st) < 0)
		die(1, "%s: %s", p->name, strerror(errno));
	if (st.st_size < b->to)
		die(1, "%s: the file shrank while read", p->name);
	if (page > 0) {
		base = at - at % page;
		len = b->to - base < WINDOW ? (size_t)(b->to - base) : WINDOW;
		m = mmap(NULL, len, PROT_READ, MAP_PRIVATE, b->fd, base);
		if (m != MAP_FAILED) {
			n = len - (size_t)(at - base);
			posix_madvise(m, len, POSIX_MADV_SEQUENTIAL);
			*lines += newlines(m + (at - base), n);
			qt_copy(m + (at - base), n, 0);
			munmap(m, len);
			return n;
		}
	}
	n = b->to - at < CHUNK ? (size_t)(b->to - at) : CHUNK;
	if ((k = readat(b->fd, chunk, n, at)) != (ssize_t)n)
		die(1, "%s: %s", p->name, k < 0 ? strerror(errno) :
		    "the file shrank while read");
	*lines += newlines(chunk, n);
	qt_copy(chunk, n, 0);
	return n;
}
