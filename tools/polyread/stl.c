/*
 * stl.c: STL, ASCII (solid, facet normal, outer loop, three vertex lines,
 * endloop, endfacet, endsolid) or binary (an 80-byte header, a 32-bit
 * triangle count, 50 bytes a triangle: a normal and three vertices as
 * little-endian floats, two bytes of attributes).  Normals are ignored:
 * the order of the vertices orients a facet.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "qtree.h"
#include "polyread.h"

static uint32_t
le32(const unsigned char *p)
{
	return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 |
	    (uint32_t)p[3] << 24;
}

static double
lefloat(const unsigned char *p)
{
	uint32_t u = le32(p);
	float f;

	memcpy(&f, &u, sizeof(f));
	return f;
}

/* ASCII: the first word is solid and facet follows; binary: a NUL byte. */
static int
isascii_stl(const struct src *s)
{
	const char *p = s->p;

	return s->nulline == 0 && strncmp(p, "solid", 5) == 0 &&
	    (p[5] == ' ' || p[5] == '\t' || p[5] == '\n' || p[5] == '\r') &&
	    strstr(p, "facet") != NULL;
}

int
isstl(const struct src *s)
{
	return isascii_stl(s) || (s->nulline > 0 && s->len >= 84);
}

/* The next word, which must be want. */
static void
word(struct src *s, const char *want)
{
	size_t n = strlen(want);

	if (!skipspace(s))
		readerr(s->name, lastline(s), "input ends where %s was "
		    "expected", want);
	if (strncmp(s->p, want, n) != 0 || (s->p[n] != '\0' &&
	    strchr(" \t\r\n", s->p[n]) == NULL))
		badtoken(s, want[0] == 'e' || want[0] == 'o' || want[0] == 'v' ||
		    want[0] == 'f' || want[0] == 'n' ? "expected an STL keyword"
		    : "unexpected word");
	s->p += n;
}

static int
isword(struct src *s, const char *w)
{
	size_t n = strlen(w);

	return skipspace(s) && strncmp(s->p, w, n) == 0 &&
	    (s->p[n] == '\0' || strchr(" \t\r\n", s->p[n]) != NULL);
}

static void
parseascii(struct src *s, struct input *in)
{
	size_t v[3];
	long line;
	int k;

	while (isword(s, "solid")) {
		s->p += 5;
		restofline(s);
		while (isword(s, "facet")) {
			line = s->line;
			s->p += 5;
			word(s, "normal");
			number(s, "normal x");
			number(s, "normal y");
			number(s, "normal z");
			word(s, "outer");
			word(s, "loop");
			for (k = 0; k < 3; k++) {
				double x, y, z;
				long vl;

				word(s, "vertex");
				vl = s->line;
				x = number(s, "x");
				y = number(s, "y");
				z = number(s, "z");
				v[k] = addpoint3(in, s->name, vl, x, y, z);
			}
			word(s, "endloop");
			word(s, "endfacet");
			addpoly3(in, s->name, line, v, 3);
		}
		word(s, "endsolid");
		restofline(s);
	}
	if (skipspace(s))
		badtoken(s, "expected solid or the end of the input");
}

/*
 * The count is checked against the file's length before anything is
 * read, so that a count that lies costs nothing.
 */
static void
parsebinary(struct src *s, struct input *in)
{
	const unsigned char *b = (const unsigned char *)s->buf;
	uint32_t n, i;
	size_t v[3];
	int k;

	if (s->len < 84)
		readerr(s->name, 1, "neither ASCII STL (solid, then facets) "
		    "nor binary (84 bytes at least): %zu bytes", s->len);
	n = le32(b + 80);
	if ((unsigned long long)n * 50 + 84 != s->len)
		readerr(s->name, 0, "binary STL of %lu triangles needs %llu "
		    "bytes, the file has %zu", (unsigned long)n,
		    (unsigned long long)n * 50 + 84, s->len);
	if (n == 0)
		readerr(s->name, 0, "binary STL of no triangles");
	for (i = 0; i < n; i++) {
		const unsigned char *t = b + 84 + 50 * (size_t)i;

		for (k = 0; k < 3; k++)
			v[k] = addpoint3(in, s->name, 0, lefloat(t + 12 + 12 * k),
			    lefloat(t + 16 + 12 * k), lefloat(t + 20 + 12 * k));
		addpoly3(in, s->name, 0, v, 3);
	}
}

void
parsestl(struct src *s, struct input *in)
{
	skipspace(s);
	if (isascii_stl(s))
		parseascii(s, in);
	else
		parsebinary(s, in);
}
