/* test_series.c - a run's series held once (src/core/blockavg.c, io.c): a series
 * that expects n samples reserves them at its first push and keeps the room
 * through a checkpoint's write and read, so that it never grows by doubling
 * (a row-1 run of pan-2008 Table 2 peaked at 2.1 GB for 0.7 GB of series); and
 * the checkpoint's checksum, summed as the bytes are written, is FNV-1a. */
#include "testutil.h"
#include "blockavg.h"
#include "io.h"

/* The first push reserves the expected samples; past them the series doubles
 * (an estimate too small costs memory, never samples); freeing keeps the count. */
static void expected_samples_reserved_at_first_push(void **state)
{
    (void)state;
    Series s = {.expect = 1000};
    assert_int_equal(series_push(&s, 1.0), 0);
    CHECK_TRUE(s.cap == 1000, "first push: cap %zu, want the 1000 expected", s.cap);
    for (int k = 1; k < 1000; k++) assert_int_equal(series_push(&s, (double)k + 1.0), 0);
    CHECK_TRUE(s.cap == 1000 && s.n == 1000, "1000 samples: cap %zu n %zu, want 1000 1000", s.cap, s.n);
    assert_int_equal(series_push(&s, 1001.0), 0);
    CHECK_TRUE(s.cap == 2000, "sample 1001 of 1000 expected: cap %zu, want 2000", s.cap);
    for (size_t k = 0; k < s.n; k++) CHECK_ABS("value kept through the growth", s.v[k], (double)k + 1.0, 0.0);
    series_free(&s);
    CHECK_TRUE(s.v == NULL && s.n == 0 && s.cap == 0 && s.expect == 1000, "freed: v %p n %zu cap %zu expect %zu",
               (void *)s.v, s.n, s.cap, s.expect);
    Series u = {0};   /* no expectation: the old growth, 256 then doubling */
    assert_int_equal(series_push(&u, 0.0), 0);
    CHECK_TRUE(u.cap == 256, "no expectation: cap %zu, want 256", u.cap);
    series_free(&u);
}

/* Write a series of n samples through an Io and read it back into r (whose
 * expectation the caller set). */
static void round_trip(size_t n, Series *r)
{
    Series w = {0};
    for (size_t k = 0; k < n; k++) assert_int_equal(series_push(&w, 0.5 * (double)k), 0);
    char *buf = NULL;
    size_t len = 0;
    FILE *mem = open_memstream(&buf, &len);
    assert_non_null(mem);
    Io out = {.reading = 0, .out = mem, .sum = IO_FNV_BASIS};
    io_series(&out, &w, "series");
    assert_int_equal(fclose(mem), 0);
    assert_false(out.bad);
    CHECK_TRUE(out.sum == io_fnv1a(buf, len, IO_FNV_BASIS), "the sum kept while writing is the bytes' FNV-1a");
    Io in = {.reading = 1, .in = (const unsigned char *)buf, .len = len};
    io_series(&in, r, "series");
    assert_false(in.bad);
    CHECK_TRUE(r->n == n, "read back %zu samples of %zu", r->n, n);
    for (size_t k = 0; k < n; k++) CHECK_ABS("value read back", r->v[k], 0.5 * (double)k, 0.0);
    free(buf);
    series_free(&w);
}

/* A resumed run reads its series with room for the samples still to come;
 * one read with more samples than expected holds exactly those. */
static void checkpoint_read_keeps_the_room(void **state)
{
    (void)state;
    Series r = {.expect = 500};
    round_trip(300, &r);
    CHECK_TRUE(r.cap == 500, "300 of 500 expected read: cap %zu, want 500", r.cap);
    assert_int_equal(series_push(&r, 1.0), 0);
    CHECK_TRUE(r.cap == 500, "a push after the read: cap %zu, want 500 (no growth)", r.cap);
    series_free(&r);
    Series big = {.expect = 100};
    round_trip(300, &big);
    CHECK_TRUE(big.cap == 300, "300 read, 100 expected: cap %zu, want 300", big.cap);
    series_free(&big);
}

/* FNV-1a 64 (Fowler, Noll & Vo; the published test vectors, from the published
 * offset basis 0xcbf29ce484222325): "a" gives 0xaf63dc4c8601ec8c, "foobar"
 * 0x85944171f73967e8; summed in parts, as a streamed checkpoint is, it equals the
 * sum of the whole. The checkpoint's own basis is 1469598103934665603, the
 * published one with its last digit dropped, as the format has always had it. */
static void fnv1a_vectors_and_parts(void **state)
{
    (void)state;
    const uint64_t published = 0xcbf29ce484222325ULL;
    CHECK_TRUE(io_fnv1a("", 0, published) == published, "FNV-1a(\"\") is the basis");
    CHECK_TRUE(io_fnv1a("a", 1, published) == 0xaf63dc4c8601ec8cULL, "FNV-1a(\"a\")");
    CHECK_TRUE(io_fnv1a("foobar", 6, published) == 0x85944171f73967e8ULL, "FNV-1a(\"foobar\")");
    CHECK_TRUE(io_fnv1a("bar", 3, io_fnv1a("foo", 3, published)) == 0x85944171f73967e8ULL,
               "FNV-1a(\"foo\" then \"bar\") = FNV-1a(\"foobar\")");
    CHECK_TRUE(IO_FNV_BASIS == 1469598103934665603ULL, "the checkpoint format's basis");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(expected_samples_reserved_at_first_push),
        cmocka_unit_test(checkpoint_read_keeps_the_room),
        cmocka_unit_test(fnv1a_vectors_and_parts),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
