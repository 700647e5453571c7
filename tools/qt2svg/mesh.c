/*
 * mesh.c: the mesh's elements, vertices and numbers, and the leaves'
 * element numbers.  Elements under 2 pixels are shaded as blocks, not
 * outlined, so that the file stays the size of the picture; only the
 * vertices and numbers of the outlined elements are drawn.
 */
#include <stdio.h>
#include <string.h>

#include "qtree.h"
#include "qt2svg.h"

/* The mesh's records, kept for the end. */
void
meshvertex(const struct meshvertex *mv)
{
	pic.verts = grow(pic.verts, &pic.vertcap, pic.nverts + 1,
	    sizeof(*pic.verts));
	pic.verts[pic.nverts++] = mv->p;
}

void
meshelem(const struct meshelem *e)
{
	pic.elems = grow(pic.elems, &pic.elemcap, pic.nelemw + 1 + e->n,
	    sizeof(*pic.elems));
	pic.elems[pic.nelemw] = e->n;
	memcpy(pic.elems + pic.nelemw + 1, e->v, e->n * sizeof(*e->v));
	pic.nelemw += 1 + e->n;
	pic.nelems++;
}

/* Inline: elembox takes every vertex of every element, more than once. */
static inline void
vertexpx(unsigned long long id, long long *x, long long *y)
{
	*x = pixelx(pic.verts[id - 1].x);
	*y = pixely(pic.verts[id - 1].y);
}

/* An element's box and centre; 0 when it lies outside the clip box. */
static int
elembox(const unsigned long long *e, long long b[4], long long c[2])
{
	long long x, y;
	unsigned long long k;

	c[0] = c[1] = 0;
	for (k = 0; k < e[0]; k++) {
		vertexpx(e[1 + k], &x, &y);
		if (k == 0 || x < b[0])
			b[0] = x;
		if (k == 0 || y < b[1])
			b[1] = y;
		if (k == 0 || x > b[2])
			b[2] = x;
		if (k == 0 || y > b[3])
			b[3] = y;
		c[0] += x;
		c[1] += y;
	}
	c[0] /= (long long)e[0];
	c[1] /= (long long)e[0];
	return b[2] >= pic.clipbox[0] && b[0] <= pic.clipbox[2] &&
	    b[3] >= pic.clipbox[1] && b[1] <= pic.clipbox[3];
}

/*
 * Elements under 2 pixels, as leaves are, are not outlined one by one:
 * the 2-pixel blocks of the map that hold their centres are shaded, so
 * that the file stays the size of the picture however fine the mesh.
 * Only the vertices and numbers of the elements outlined are drawn.
 */
#define FINE	200	/* hundredths */

static struct {
	unsigned char	*block;		/* a byte a 2-pixel block of the map */
	size_t		 w, h;
	unsigned char	*vdrawn;	/* a bit a vertex: of an outlined one */
} fine;

static int
outlined(const long long b[4])
{
	return b[2] - b[0] >= FINE && b[3] - b[1] >= FINE;
}

/* The smallest side drawn, of an outlined element or the smallest leaf. */
double
finest(void)
{
	const unsigned long long *e = pic.elems;
	long long b[4], c[2];
	double f = -1, s;
	size_t i;

	for (i = 0; i < pic.nelems; i++, e += 1 + e[0]) {
		if (!elembox(e, b, c) || !outlined(b))
			continue;
		s = (b[2] - b[0] < b[3] - b[1] ? b[2] - b[0] : b[3] - b[1]) /
		    100.0;
		if (f < 0 || s < f)
			f = s;
	}
	if (pic.deepest >= 0 && (f < 0 || cellpixels(pic.deepest) < f))
		f = cellpixels(pic.deepest);
	return f >= 0 ? f : mapside();
}

/* A layer of black lines, width pixels wide, clipped to the map. */
static void
strokelayer(struct layer *ly, char head[256], const char *id, double width,
    const char *style)
{
	char num[32];

	fmthund(num, hund(width));
	snprintf(head, 256, "<g id=\"%s\" fill=\"none\" stroke=\"#000000\" "
	    "stroke-width=\"%s\" %s clip-path=\"url(#map)\">\n", id, num,
	    style);
	ly->head = head;
	ly->attrs = "";
}

static void
markfine(const long long c[2])
{
	long long bx = (c[0] - pic.box[0]) / FINE, by = (c[1] - pic.box[1]) / FINE;

	if (fine.block == NULL) {
		fine.w = (size_t)((pic.box[2] - pic.box[0]) / FINE + 1);
		fine.h = (size_t)((pic.box[3] - pic.box[1]) / FINE + 1);
		fine.block = xreallocarray(NULL, fine.w, fine.h);
		memset(fine.block, 0, fine.w * fine.h);
	}
	if (bx >= 0 && by >= 0 && (size_t)bx < fine.w && (size_t)by < fine.h)
		fine.block[(size_t)by * fine.w + (size_t)bx] = 1;
}

static int
vertexdrawn(size_t id)
{
	return fine.vdrawn[(id - 1) / 8] >> ((id - 1) % 8) & 1;
}

/* The shaded blocks, a rectangle a run along each row. */
static void
fineblocks(void)
{
	struct layer ly = { 0 };
	size_t i, j, e;

	if (fine.block == NULL)
		return;
	ly.head = "<g id=\"fine-elements\" fill=\"#000000\" "
	    "fill-opacity=\"0.35\" shape-rendering=\"crispEdges\">\n";
	ly.attrs = "";
	for (j = 0; j < fine.h; j++)
		for (i = 0; i < fine.w; i = e) {
			const unsigned char *row = fine.block + j * fine.w;

			for (e = i + 1; e < fine.w && row[e] == row[i]; e++)
				;
			if (!row[i])
				continue;
			subpath(&ly);
			out("M", 1);
			outxy(pic.box[0] + (long long)i * FINE,
			    pic.box[1] + (long long)j * FINE);
			out("h", 1);
			outhund((long long)(e - i) * FINE);
			out("v", 1);
			outhund(FINE);
			out("h", 1);
			outhund(-(long long)(e - i) * FINE);
			out("z", 1);
		}
	layerend(&ly);
}

/* Elements use only vertices defined before them. */
void
elements(double f)
{
	const unsigned long long *e = pic.elems;
	struct layer ly = { 0 };
	char head[256];
	long long b[4], c[2], x, y;
	unsigned long long k;
	size_t i;

	fine.vdrawn = xreallocarray(NULL, pic.nverts / 8 + 1, 1);
	memset(fine.vdrawn, 0, pic.nverts / 8 + 1);
	strokelayer(&ly, head, "elements", clamp(f / 8, 0.01, 1),
	    "stroke-linejoin=\"round\"");
	for (i = 0; i < pic.nelems; i++, e += 1 + e[0]) {
		if (!elembox(e, b, c))
			continue;
		if (!outlined(b)) {
			markfine(c);
			continue;
		}
		subpath(&ly);
		for (k = 0; k < e[0]; k++) {
			vertexpx(e[1 + k], &x, &y);
			out(k == 0 ? "M" : " ", 1);
			outxy(x, y);
			fine.vdrawn[(e[1 + k] - 1) / 8] |= 1 << (e[1 + k] - 1) % 8;
		}
		out("z", 1);
	}
	layerend(&ly);
	fineblocks();
}

/* A zero-length line with round caps is a dot. */
void
vertices(double f)
{
	struct layer ly = { 0 };
	char head[256];
	long long x, y;
	size_t i;

	strokelayer(&ly, head, "vertices", clamp(f / 5, 0.5, 5),
	    "stroke-linecap=\"round\"");
	for (i = 0; i < pic.nverts; i++) {
		vertexpx(i + 1, &x, &y);
		if (outcode(x, y) != 0 || !vertexdrawn(i + 1))
			continue;
		subpath(&ly);
		out("M", 1);
		outxy(x, y);
		out("h0", 2);
	}
	layerend(&ly);
}

/*
 * A number whose digits' middle is at x, y, as large as the cell allows
 * and no larger than the legend's text, kept inside the picture: a digit
 * is at most 0.6 of the font size wide and rises 0.75 of it.
 */
static void
label(long long x, long long y, double size, unsigned long long id)
{
	char num[24];
	double fs;
	int digits = fmtint(num, (long long)id) - num;
	long long half;

	fs = clamp(size * 1.4 / (digits > 2 ? digits : 2), 0.01, 12);
	half = hund(0.3 * fs * digits);
	outs("<text x=\"");
	outhund(clampll(x, half, opt.width * 100LL - half));
	outs("\" y=\"");
	outhund(clampll(y + hund(0.35 * fs), hund(0.75 * fs), mapbottom()));
	outs("\" font-size=\"");
	outhund(hund(fs));
	outs("\">");
	outs(num);
	outs("</text>\n");
}

void
numbers(double f)
{
	const unsigned long long *e = pic.elems;
	long long b[4], c[2], x, y, fs, w;
	char num[24];
	size_t i;
	int digits;

	if (opt.nflag && (pic.nelems > 0 || pic.numbered)) {
		outs("<g id=\"element-numbers\" font-family=\"sans-serif\" "
		    "text-anchor=\"middle\" fill=\"#000000\">\n");
		for (i = 0; i < pic.nelems; i++, e += 1 + e[0])
			if (elembox(e, b, c) && outlined(b))
				label(c[0], c[1], (b[2] - b[0]) / 100.0, i + 1);
		for (i = 0; pic.nelems == 0 && i < pic.nsq; i++) {
			const struct square *s = &pic.sq[i];

			if (s->id > 0 &&
			    cellbox(s->level, s->ix, s->ix + 1, s->iy, b))
				label((b[0] + b[2]) / 2, (b[1] + b[3]) / 2,
				    (b[2] - b[0]) / 100.0, s->id);
		}
		outs("</g>\n");
	}
	if (!opt.Nflag || pic.nverts == 0)
		return;
	fs = hund(clamp(f / 3, 1, 10));
	outs("<g id=\"vertex-numbers\" font-family=\"sans-serif\" "
	    "font-size=\"");
	outhund(fs);
	outs("\" fill=\"#000000\">\n");
	/* Above and to the right of the dot, clear of its lines. */
	for (i = 0; i < pic.nverts; i++) {
		vertexpx(i + 1, &x, &y);
		if (outcode(x, y) != 0 || !vertexdrawn(i + 1))
			continue;
		digits = fmtint(num, (long long)i + 1) - num;
		w = 6 * fs * digits / 10;
		outs("<text x=\"");
		outhund(clampll(x + 150, 0, opt.width * 100LL - w));
		outs("\" y=\"");
		outhund(clampll(y - 150, 3 * fs / 4, mapbottom()));
		outs("\">");
		outs(num);
		outs("</text>\n");
	}
	outs("</g>\n");
}
