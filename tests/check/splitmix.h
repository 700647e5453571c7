/*
 * splitmix.h: splitmix64, a full-period 64-bit generator, enough to
 * spread the test programs' inputs; the same sequence on every machine.
 * With it the draws and the bit casts the test programs share (inline,
 * so a program that does not use one is not warned about it).
 */
static uint64_t rngstate = 12345;

static uint64_t
rnd(void)
{
	uint64_t z = (rngstate += 0x9e3779b97f4a7c15);

	z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9;
	z = (z ^ (z >> 27)) * 0x94d049bb133111eb;
	return z ^ (z >> 31);
}

/* A uniform integer in 0..n (inclusive), n < 2^63. */
static inline uint64_t
rndupto(uint64_t n)
{
	return rnd() % (n + 1);
}

/* The double whose bits are u. */
static inline double
frombits(uint64_t u)
{
	double v;

	memcpy(&v, &u, sizeof(v));
	return v;
}
