/*
 * legend.c: the legend below the map: a row for each leaf class drawn
 * (with a mesh, the elements of each, or -q's scale of angles), each
 * object's outer rings and holes, the elements and the vertices, with
 * their counts and swatches drawn the way the map draws them; then the
 * scale bar, the tree's level and the window, as -b takes it.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "qtree.h"
#include "qt2svg.h"

void
legendrow(int row, const char *swatch, const char *text, long long count)
{
	char num[24];
	long long top = mapbottom() + (long long)(ROW * row + 2) * 100;

	fmtint(num, count);
	outs(swatch);
	outs(" x=\"");
	outhund((long long)opt.margin * 100);
	outs("\" y=\"");
	outhund(top);
	outs("\" width=\"12\" height=\"12\"/>\n<text x=\"");
	outhund((long long)(opt.margin + 18) * 100);
	outs("\" y=\"");
	outhund(top + 1050);
	outs("\">");
	outs(text);
	outs(" ");
	outs(num);
	outs("</text>\n");
}

int
legendrows(void)
{
	int k, n = 0;

	if (pic.nelems > 0 && opt.qflag)
		n += 3;
	else
		for (k = 0; k < NCLASS; k++)
			n += opt.drawn[k];
	if (pic.nelems > 0 && !opt.qflag)
		n += pic.nfill[FILLNOLEAF] > 0;
	for (k = 0; k <= pic.object; k++)
		n += (pic.nring[k][0] > 0) + (pic.nring[k][1] > 0);
	return n + (pic.nelems > 0) + (pic.nverts > 0) + 2;
}

/*
 * The scale bar's length in world units, 1, 2 or 5 times a power of ten,
 * the largest that is at most a quarter of the map's width, as text; the
 * bar is drawn from the value that text reads as.
 */
static double
scalebar(char *text)
{
	double target = mapside() / 4.0 / pic.win.scale, v;
	const char *end;
	int k = (int)floor(log10(target)), digit, i;
	char *p = text;

	v = target / pow(10, k);
	digit = v >= 5 ? 5 : v >= 2 ? 2 : 1;
	if (k < -6 || k > 6)
		snprintf(text, 32, "%de%d", digit, k);
	else {
		if (k < 0) {
			*p++ = '0';
			*p++ = '.';
			for (i = -1; i > k; i--)
				*p++ = '0';
		}
		*p++ = '0' + digit;
		for (i = 0; i < k; i++)
			*p++ = '0';
		*p = '\0';
	}
	if (parsereal(text, &end, &v) < 0)
		v = 0;
	return v;
}

/* A window's coordinate, to a pixel or finer. */
static char *
fmtwindow(char *p, double v)
{
	int d = (int)clamp(ceil(log10(pic.win.scale)), 0, 17);
	double t = pow(10, d), r = round(v * t) / t;

	return fmtreal(p, isfinite(r) ? r : v);
}

/* The four corners, as -b takes them. */
void
outwindow(int exact)
{
	const struct window *w = &pic.win;
	char num[32];
	double v[4] = { w->x0, w->y0, w->x1, w->y1 };
	int i;

	for (i = 0; i < 4; i++) {
		if (exact)
			fmtreal(num, v[i]);
		else
			fmtwindow(num, v[i]);
		if (i > 0)
			out(",", 1);
		outs(num);
	}
}

/* The scale bar, and the tree's level and the window. */
static void
legendscale(int row)
{
	char text[32];
	long long top = mapbottom() + (long long)(ROW * row + 2) * 100;
	long long x = (long long)opt.margin * 100;
	long long len = hund(scalebar(text) * pic.win.scale);

	outs("<path d=\"M");
	outxy(x, top + 600);
	out("h", 1);
	outhund(len);
	out("M", 1);
	outxy(x, top);
	outs("v12M");
	outxy(x + len, top);
	outs("v12\" fill=\"none\" stroke=\"#000000\" "
	    "stroke-width=\"1.5\"/>\n<text x=\"");
	outhund(x + len + 600);
	outs("\" y=\"");
	outhund(top + 1050);
	outs("\">");
	outs(text);
	outs(strcmp(text, "1") == 0 ? " unit" : " units");
	outs("</text>\n<text x=\"");
	top += ROW * 100;
	outhund(x);
	outs("\" y=\"");
	outhund(top + 1050);
	outs("\">");
	if (pic.level >= 0 || pic.deepest >= 0) {
		fmtint(text, pic.level >= 0 ? pic.level : pic.deepest);
		outs("level ");
		outs(text);
		outs(", ");
	}
	outs("window ");
	outwindow(0);
	outs("</text>\n");
}

#define BINW	30	/* the width of a bin of -q's scale, pixels */

void
legendtext(long long x, long long top, const char *anchor, const char *text)
{
	outs("<text x=\"");
	outhund(x);
	outs("\" y=\"");
	outhund(top + 1050);
	outs("\"");
	if (anchor != NULL) {
		outs(" text-anchor=\"");
		outs(anchor);
		outs("\"");
	}
	outs(">");
	outs(text);
	outs("</text>\n");
}

/*
 * -q's scale, in three rows: the bins' colours side by side with the
 * counts of the poorest and the best elements, then the bounds between
 * them in a triangle's degrees and in a quadrilateral's.
 */
static void
anglescale(int row)
{
	char text[80], poor[24], good[24];
	long long top = mapbottom() + (long long)(ROW * row + 2) * 100;
	long long x = (long long)opt.margin * 100, after = x + (NQBIN * BINW +
	    6) * 100;
	int i, q;

	outs("<g id=\"angle-scale\" stroke=\"#000000\" "
	    "stroke-width=\"0.5\">\n");
	for (i = 0; i < NQBIN; i++) {
		outs("<rect x=\"");
		outhund(x + (long long)i * BINW * 100);
		outs("\" y=\"");
		outhund(top);
		outs("\" width=\"");
		outhund(BINW * 100);
		outs("\" height=\"12\" fill=\"");
		outs(anglecolour[i]);
		outs("\"/>\n");
	}
	outs("</g>\n");
	fmtint(poor, pic.nfill[FILLQ]);
	fmtint(good, pic.nfill[FILLQ + NQBIN - 1]);
	snprintf(text, sizeof(text), "smallest angle: %s poor, %s good", poor,
	    good);
	legendtext(after, top, NULL, text);
	for (q = 1; q <= 2; q++) {
		top += ROW * 100;
		for (i = 0; i < NQBIN - 1; i++) {
			snprintf(text, sizeof(text), "%d\302\260",
			    q * anglebound[i]);
			legendtext(x + (long long)(i + 1) * BINW * 100, top,
			    "middle", text);
		}
		legendtext(after, top, NULL, q == 1 ? "triangles" :
		    "quadrilaterals");
	}
}

void
legend(void)
{
	char swatch[256], text[64], style[64];
	long j;
	int h, k, row = 0;

	outs("<g id=\"legend\" font-family=\"sans-serif\" font-size=\"12\">\n");
	if (pic.nelems > 0 && opt.qflag) {
		anglescale(row);
		row += 3;
	}
	for (k = 0; k < NCLASS; k++) {
		if (!opt.drawn[k] || (pic.nelems > 0 && opt.qflag))
			continue;
		snprintf(text, sizeof(text), "%c %s", classletter[k],
		    classname[k]);
		if (pic.nelems == 0) {
			snprintf(swatch, sizeof(swatch), "<rect fill=\"%s\" "
			    "stroke=\"#000000\" stroke-opacity=\"0.35\"",
			    classcolour[k]);
			legendrow(row++, swatch, text, pic.n[k]);
			continue;
		}
		snprintf(swatch, sizeof(swatch), "<rect fill=\"%s\" "
		    "stroke=\"#000000\"", classcolour[k]);
		strcat(text, ": elements");
		legendrow(row++, swatch, text, pic.nfill[k]);
	}
	if (pic.nelems > 0 && !opt.qflag && pic.nfill[FILLNOLEAF] > 0) {
		snprintf(swatch, sizeof(swatch), "<rect fill=\"%s\" "
		    "stroke=\"#000000\"", fillcolour(FILLNOLEAF));
		legendrow(row++, swatch, "no leaf: elements",
		    pic.nfill[FILLNOLEAF]);
	}
	/* Ring and mesh swatches are squares drawn the way the map draws. */
	for (j = 0; j <= pic.object; j++) {
		for (h = 0; h < 2; h++) {
			if (pic.nring[j][h] == 0)
				continue;
			snprintf(swatch, sizeof(swatch), "<rect fill=\"none\" "
			    "%s%s%s", objectstyle(style, sizeof(style), j),
			    h ? " " : "", h ? holestyle : "");
			if (j > 0)
				snprintf(text, sizeof(text), "object %ld %s", j,
				    h ? "holes" : "outer rings");
			legendrow(row++, swatch, j > 0 ? text :
			    h ? "holes" : "outer rings", pic.nring[j][h]);
		}
	}
	if (pic.nelems > 0)
		legendrow(row++, "<rect fill=\"none\" stroke=\"#000000\"",
		    "elements", pic.nelems);
	if (pic.nverts > 0)
		legendrow(row++, "<rect fill=\"#000000\" rx=\"6\"",
		    "vertices", pic.nverts);
	legendscale(row);
	outs("</g>\n");
}
