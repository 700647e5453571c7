/*
 * mesh.c: the mesh's elements, vertices and numbers, and the leaves'
 * element numbers.  Elements are filled, by their leaf's class or with -q
 * by their smallest angle, and outlined; those under 2 pixels are shaded
 * as blocks instead, so that the file stays the size of the picture; only
 * the vertices and numbers of the outlined elements are drawn.
 */
#include <stdio.h>
#include <string.h>

#include "qtree.h"
#include "qt2svg.h"

/* The neutral fill of an element that no leaf numbers. */
#define NOLEAFCOLOUR "#D9D9D9"

/*
 * A leaf's element number, kept for the elements that follow: an
 * element's leaf is the last one before it whose number is at most the
 * element's (qtree(5)).  A leaf hides every leaf before it whose number
 * is as large or larger, so the table's numbers increase, and a leaf of
 * the class of the entry before it adds nothing.
 */
void
leafnumber(unsigned long long id, int k)
{
	if (id == 0)
		return;
	while (pic.nlnum > 0 && pic.lnum[pic.nlnum - 1].id >= id)
		pic.nlnum--;
	if (pic.nlnum > 0 && pic.lnum[pic.nlnum - 1].k == k)
		return;
	pic.lnum = xgrow(pic.lnum, &pic.lnumcap, pic.nlnum + 1,
	    sizeof(*pic.lnum));
	pic.lnum[pic.nlnum].id = id;
	pic.lnum[pic.nlnum++].k = k;
}

/* The class of the leaf of element id, FILLNOLEAF for none. */
static int
elemclass(unsigned long long id)
{
	size_t lo = 0, hi = pic.nlnum, mid;

	/* the first entry past id */
	while (lo < hi) {
		mid = lo + (hi - lo) / 2;
		if (pic.lnum[mid].id <= id)
			lo = mid + 1;
		else
			hi = mid;
	}
	return lo > 0 ? pic.lnum[lo - 1].k : FILLNOLEAF;
}

/* The mesh's records, kept for the end. */
void
meshvertex(const struct meshvertex *mv)
{
	pic.verts = xgrow(pic.verts, &pic.vertcap, pic.nverts + 1,
	    sizeof(*pic.verts));
	pic.verts[pic.nverts++] = mv->p;
}

void
meshelem(const struct meshelem *e)
{
	pic.elems = xgrow(pic.elems, &pic.elemcap, pic.nelemw + 1 + e->n,
	    sizeof(*pic.elems));
	pic.elems[pic.nelemw] = e->n;
	memcpy(pic.elems + pic.nelemw + 1, e->v, e->n * sizeof(*e->v));
	pic.nelemw += 1 + e->n;
	pic.efill = xgrow(pic.efill, &pic.efillcap, pic.nelems + 1, 1);
	pic.efill[pic.nelems++] = elemclass(e->id);
}

const char *
fillcolour(int f)
{
	if (f < NCLASS)
		return classcolour[f];
	if (f == FILLNOLEAF)
		return NOLEAFCOLOUR;
	return anglecolour[f - FILLQ];
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
 * the 2-pixel blocks of the map that their boxes meet are filled and
 * shaded, so that the file stays the size of the picture however fine the
 * mesh.  Only the vertices and numbers of the elements outlined are drawn.
 */
#define FINE	200	/* hundredths */
#define BLOCKANY 0x80	/* an element meets the block */

static struct {
	unsigned char	*block;		/* a byte a 2-pixel block of the map:
					   BLOCKANY, and the fills' bits or
					   with -q the poorest bin + 1 */
	size_t		 w, h;
	unsigned char	*vdrawn;	/* a bit a vertex: of an outlined one */
} fine;

static int
outlined(const long long b[4])
{
	return b[2] - b[0] >= FINE && b[3] - b[1] >= FINE;
}

/* An element's byte in pic.efill once elementfills has run. */
#define EFILL		0x1f	/* its fill, NOFILL for none */
#define EOUTSIDE	0x40	/* wholly outside the clip box */
#define EOUTLINED	0x80	/* 2 pixels or more across and high */

/*
 * Each element's fill, from its leaf's class or its smallest angle, and
 * whether it is drawn and outlined; the elements drawn per fill, for the
 * legend; and the smallest side drawn, of an outlined element or the
 * smallest leaf.
 */
double
elementfills(void)
{
	const unsigned long long *e = pic.elems;
	long long b[4], c[2];
	double f = -1, s;
	size_t i;
	int fill, k;

	for (i = 0; i < pic.nelems; i++, e += 1 + e[0]) {
		k = pic.efill[i];
		if (!elembox(e, b, c)) {
			pic.efill[i] = EOUTSIDE;
			continue;
		}
		if (k < NCLASS && !opt.drawn[k])
			fill = NOFILL;
		else
			fill = opt.qflag ? FILLQ + anglebin(e) : k;
		if (fill != NOFILL)
			pic.nfill[fill]++;
		pic.efill[i] = fill;
		if (!outlined(b))
			continue;
		pic.efill[i] |= EOUTLINED;
		s = (b[2] - b[0] < b[3] - b[1] ? b[2] - b[0] : b[3] - b[1]) /
		    100.0;
		if (f < 0 || s < f)
			f = s;
	}
	if (pic.deepest >= 0 && (f < 0 || cellpixels(pic.deepest) < f))
		f = cellpixels(pic.deepest);
	return f >= 0 ? f : mapside();
}

/* A layer of black lines, width pixels wide, clipped to clip. */
static void
strokelayer(struct layer *ly, char head[256], const char *id, double width,
    const char *style, const char *clip)
{
	char num[32];

	fmthund(num, hund(width));
	snprintf(head, 256, "<g id=\"%s\" fill=\"none\" stroke=\"#000000\" "
	    "stroke-width=\"%s\" %s clip-path=\"url(#%s)\">\n", id, num,
	    style, clip);
	ly->head = head;
	ly->attrs = "";
}

/* The blocks that an element's box meets take its fill. */
static void
markfine(const long long b[4], int fill)
{
	long long x0, y0, x1, y1, x, y;
	unsigned char *v;

	if (fine.block == NULL) {
		fine.w = (size_t)((pic.box[2] - pic.box[0]) / FINE + 1);
		fine.h = (size_t)((pic.box[3] - pic.box[1]) / FINE + 1);
		fine.block = xreallocarray(NULL, fine.w, fine.h);
		memset(fine.block, 0, fine.w * fine.h);
	}
	/* the box's right and bottom edges are not in it */
	x0 = (clampll(b[0], pic.box[0], pic.box[2]) - pic.box[0]) / FINE;
	y0 = (clampll(b[1], pic.box[1], pic.box[3]) - pic.box[1]) / FINE;
	x1 = (clampll(b[2] > b[0] ? b[2] - 1 : b[0], pic.box[0], pic.box[2]) -
	    pic.box[0]) / FINE;
	y1 = (clampll(b[3] > b[1] ? b[3] - 1 : b[1], pic.box[1], pic.box[3]) -
	    pic.box[1]) / FINE;
	for (y = y0; y <= y1; y++)
		for (x = x0; x <= x1; x++) {
			v = &fine.block[(size_t)y * fine.w + (size_t)x];
			*v |= BLOCKANY;
			if (fill == NOFILL)
				continue;
			if (!opt.qflag)
				*v |= 1 << fill;
			else if ((*v & 7) == 0 || fill - FILLQ + 1 < (*v & 7))
				*v = BLOCKANY | (fill - FILLQ + 1);
		}
}

/*
 * A block's fill: with -q its poorest bin's; else, as leaves' blocks
 * take theirs, P when it holds an element of a partial leaf, or of both a
 * full and an empty one, then F, E, and no leaf.
 */
static int
blockfill(unsigned char v)
{
	if (opt.qflag)
		return (v & 7) != 0 ? FILLQ + (v & 7) - 1 : NOFILL;
	if (v & 1 << CP || (v & 1 << CF && v & 1 << CE))
		return opt.drawn[CP] ? CP : CF;
	if (v & 1 << CF)
		return CF;
	if (v & 1 << CE)
		return CE;
	return v & 1 << FILLNOLEAF ? FILLNOLEAF : NOFILL;
}

static int
vertexdrawn(size_t id)
{
	return fine.vdrawn[(id - 1) / 8] >> ((id - 1) % 8) & 1;
}

/*
 * The runs along each row of the blocks whose fill is fill, a rectangle
 * each; with NFILL, the runs of blocks that any element meets.
 */
static void
fineruns(struct layer *ly, int fill)
{
	const unsigned char *row;
	size_t i, j, e;

	for (j = 0; j < fine.h; j++) {
		row = fine.block + j * fine.w;
		for (i = 0; i < fine.w; i = e) {
			if (fill == NFILL) {
				for (e = i + 1; e < fine.w &&
				    (row[e] != 0) == (row[i] != 0); e++)
					;
				if (row[i] == 0)
					continue;
			} else {
				for (e = i + 1; e < fine.w &&
				    blockfill(row[e]) == blockfill(row[i]); e++)
					;
				if (blockfill(row[i]) != fill)
					continue;
			}
			subpath(ly);
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
	}
}

/*
 * The blocks filled, a fill at a time, then shaded black at 35% opacity
 * as the lines of elements finer than the pixels would shade them.
 */
static void
fineblocks(void)
{
	struct layer ly = { 0 };
	char attrs[NFILL][64];
	int k;

	if (fine.block == NULL)
		return;
	ly.head = "<g id=\"fine-elements\" shape-rendering=\"crispEdges\" "
	    "clip-path=\"url(#mesh)\">\n";
	for (k = 0; k < NFILL; k++) {
		snprintf(attrs[k], sizeof(attrs[k]), "fill=\"%s\" ",
		    fillcolour(k));
		pathattrs(&ly, attrs[k]);
		fineruns(&ly, k);
	}
	pathattrs(&ly, "fill=\"#000000\" fill-opacity=\"0.35\" ");
	fineruns(&ly, NFILL);
	layerend(&ly);
}

/*
 * The elements outlined, a fill at a time, then those with none; the
 * blocks of the others.  Elements use only vertices defined before them.
 */
void
elements(double f)
{
	const unsigned long long *e;
	struct layer ly = { 0 };
	char head[256], attrs[NFILL + 1][64];
	long long b[4], c[2], x, y;
	unsigned long long k;
	size_t i;
	int fill;

	fine.vdrawn = xreallocarray(NULL, pic.nverts / 8 + 1, 1);
	memset(fine.vdrawn, 0, pic.nverts / 8 + 1);
	e = pic.elems;
	for (i = 0; i < pic.nelems; i++, e += 1 + e[0])
		if (!(pic.efill[i] & (EOUTSIDE | EOUTLINED)) &&
		    elembox(e, b, c))
			markfine(b, pic.efill[i] & EFILL);
	strokelayer(&ly, head, "elements", clamp(f / 8, 0.01, 1),
	    "stroke-linejoin=\"round\"", "mesh");
	for (fill = 0; fill <= NFILL; fill++) {
		if (fill < NFILL)
			snprintf(attrs[fill], sizeof(attrs[fill]),
			    "fill=\"%s\" ", fillcolour(fill));
		else
			attrs[fill][0] = '\0';
		pathattrs(&ly, attrs[fill]);
		e = pic.elems;
		for (i = 0; i < pic.nelems; i++, e += 1 + e[0]) {
			if (pic.efill[i] != (EOUTLINED |
			    (fill < NFILL ? fill : NOFILL)))
				continue;
			subpath(&ly);
			for (k = 0; k < e[0]; k++) {
				vertexpx(e[1 + k], &x, &y);
				out(k == 0 ? "M" : " ", 1);
				outxy(x, y);
				fine.vdrawn[(e[1 + k] - 1) / 8] |=
				    1 << (e[1 + k] - 1) % 8;
			}
			out("z", 1);
		}
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
	    "stroke-linecap=\"round\"", "map");
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
