/*
 * Combined streams (qtbool): the operators' names and the op record's
 * expression, which the reader checks and the writer spells.
 */
#include <string.h>

#include "qtree.h"

static const char *const opnames[] = { NULL, "and", "or", "minus", "xor" };

/* The operator a word names, 0 for none. */
int
op_code(const char *word)
{
	int k;

	for (k = QT_AND; k <= QT_XOR; k++)
		if (strcmp(word, opnames[k]) == 0)
			return k;
	return 0;
}

const char *
op_name(int op)
{
	return op >= QT_AND && op <= QT_XOR ? opnames[op] : "?";
}

/*
 * The n words of an op record after its tag, into term: an operator as
 * its negated code, an object as its number.  They must be a prefix
 * expression of binary operators over the objects 1 to nobjects, each
 * once, in order.  Returns NULL, or what is wrong.
 */
const char *
op_terms(char *const *word, int n, long nobjects, int *term)
{
	const char *end;
	long long v;
	long next = 1;
	int i, need = 1, op;

	for (i = 0; i < n; i++) {
		if (need == 0)
			return "op expression goes on after its end";
		if ((op = op_code(word[i])) != 0) {
			term[i] = -op;
			need++;
			continue;
		}
		if (parselong(word[i], &end, &v) < 0 || *end != '\0' ||
		    v != next)
			return "op expression: a word that is neither an "
			    "operator (and, or, minus, xor) nor the next "
			    "object's number";
		if (next > nobjects)
			return "op expression names an object that no object "
			    "record before it gives";
		term[i] = (int)next++;
		need--;
	}
	if (need > 0)
		return "op expression ends before its operands";
	if (next - 1 != nobjects)
		return "op expression leaves objects out";
	return NULL;
}
