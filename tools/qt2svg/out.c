/*
 * out.c: the bytes of the picture.  Everything goes to stdout through
 * out(), which checks each write; numbers are whole hundredths of a pixel,
 * written without trailing zeros by fmthund, not printf, because a large
 * picture is mostly numbers.  Leaves' rectangles reuse the texts of the
 * last numbers of each kind, the cache below, and layers cut paths into
 * elements of at most CHUNK subpaths.  The cache, rect and the layers are
 * here together so that the hot path of a leaf stays in one file, where
 * the compiler can inline it.
 */
#include <errno.h>
#include <stdio.h>
#include <string.h>

#include "qtree.h"
#include "qt2svg.h"

/* Hundredths as a decimal without trailing zeros: 1250 is "12.5". */
char *
fmthund(char *p, long long v)
{
	unsigned long long a = v < 0 ? -(unsigned long long)v :
	    (unsigned long long)v;
	uint32_t q, frac = a % 100;
	int i, n;

	if (v < 0)
		*p++ = '-';
	if (a >= 100000000)	/* a million pixels or more: rare */
		p = fmtint(p, (long long)(a / 100));
	else {
		/* four numbers a leaf: fmtint's generality would show */
		q = (uint32_t)(a / 100);
		n = 1 + (q >= 10) + (q >= 100) + (q >= 1000) + (q >= 10000) +
		    (q >= 100000);
		for (i = n - 1; i >= 0; i--) {
			p[i] = '0' + q % 10;
			q /= 10;
		}
		p += n;
	}
	if (frac != 0) {
		*p++ = '.';
		*p++ = '0' + frac / 10;
		if (frac % 10 != 0)
			*p++ = '0' + frac % 10;
	}
	*p = '\0';
	return p;
}

/*
 * The texts of the last numbers of each kind, per level: neighbours share
 * columns, rows and sides, and formatting is most of a leaf's cost.
 */
struct numtext {
	long long	v;
	char		s[24];	/* copied whole */
	size_t		len;	/* 0 when empty */
};

#define NKEPT	8	/* columns or rows kept per level */
static struct leveltexts {
	struct numtext	x[NKEPT], y[NKEPT];	/* by column, by row */
	struct numtext	side[3][2];	/* h, v, h back: two widths each */
} kept[QT_MAXLEVEL + 1];

static char *
putnum(char *p, struct numtext *t, long long v)
{
	if (t->len == 0 || t->v != v) {
		t->v = v;
		t->len = fmthund(t->s, v) - t->s;
	}
	memcpy(p, t->s, sizeof(t->s));
	return p + t->len;
}

void
out(const char *s, size_t n)
{
	if (n > 0 && fwrite(s, 1, n, stdout) != n)
		die(1, "write error: %s", strerror(errno ? errno : EIO));
}

void
outs(const char *s)
{
	out(s, strlen(s));
}

void
outhund(long long v)
{
	char tmp[32];

	out(tmp, fmthund(tmp, v) - tmp);
}

/* A pair "X Y" in hundredths. */
void
outxy(long long x, long long y)
{
	outhund(x);
	out(" ", 1);
	outhund(y);
}

void
subpath(struct layer *ly)
{
	if (!ly->open) {
		outs(ly->head);
		ly->open = 1;
	}
	if (ly->n % CHUNK == 0) {
		if (ly->n > 0)
			outs("\"/>\n");
		outs("<path ");
		outs(ly->attrs);
		outs("d=\"");
	}
	ly->n++;
}

/* Ends the path elements; the next ones take attrs. */
void
pathattrs(struct layer *ly, const char *attrs)
{
	if (ly->n > 0)
		outs("\"/>\n");
	ly->n = 0;
	ly->attrs = attrs;
}

void
layerend(struct layer *ly)
{
	pathattrs(ly, "");
	if (ly->open)
		outs("</g>\n");
	ly->open = 0;
}

/* A rectangle from its upper left corner across, down and back. */
void
rect(struct layer *ly, int level, uint64_t ix, uint64_t iy, long long x0,
    long long x1, long long y0, long long y1)
{
	struct leveltexts *t = &kept[level];
	char buf[5 * sizeof(struct numtext) + 8], *p = buf;

	subpath(ly);
	*p++ = 'M';
	p = putnum(p, &t->x[ix % NKEPT], x0);
	*p++ = ' ';
	p = putnum(p, &t->y[iy % NKEPT], y1);
	*p++ = 'h';
	p = putnum(p, &t->side[0][(x1 - x0) & 1], x1 - x0);
	*p++ = 'v';
	p = putnum(p, &t->side[1][(y0 - y1) & 1], y0 - y1);
	*p++ = 'h';
	p = putnum(p, &t->side[2][(x0 - x1) & 1], x0 - x1);
	*p++ = 'z';
	out(buf, p - buf);
}
