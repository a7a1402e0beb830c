/* Shared helpers of the tests that run the built `prox` executable (PROX_CLI_PATH, set by
 * tests/CMakeLists.txt; empty when the CLI is not built): run it and read its output, count matches,
 * write a temporary deck, read a vector out of its JSON. The including file defines
 * _POSIX_C_SOURCE (popen, mkstemp) before any system header. */
#ifndef PROX_TEST_CLI_UTIL_H
#define PROX_TEST_CLI_UTIL_H

#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "test_util.h"

static inline int have_cli(void) { return PROX_CLI_PATH[0] != 0; }

/* Runs the CLI with `args` after the environment settings `env`; returns its exit status and its
 * stdout (malloc'd) in *out. */
static inline int run_cli_env(const char *env, const char *args, char **out)
{
    char cmd[4096];
    snprintf(cmd, sizeof cmd, "%s '%s' %s 2>/dev/null", env, PROX_CLI_PATH, args);
    FILE *p = popen(cmd, "r");
    assert_non_null(p);
    size_t n = 0, cap = 1 << 16;
    char *buf = malloc(cap);
    assert_non_null(buf);
    for (size_t got; (got = fread(buf + n, 1, cap - n - 1, p)) > 0;) {
        n += got;
        if (cap - n < 1024) {
            cap *= 2;
            buf = realloc(buf, cap);
            assert_non_null(buf);
        }
    }
    buf[n] = 0;
    int st = pclose(p);
    assert_true(WIFEXITED(st));
    *out = buf;
    return WEXITSTATUS(st);
}

static inline int run_cli(const char *args, char **out) { return run_cli_env("", args, out); }

/* Number of occurrences of needle in hay. */
static inline size_t count(const char *hay, const char *needle)
{
    size_t c = 0;
    for (const char *s = hay; (s = strstr(s, needle)) != NULL; s += strlen(needle)) ++c;
    return c;
}

/* Writes text to a fresh temporary file and puts its path in path. */
static inline void temp_deck(const char *text, char path[64])
{
    strcpy(path, "/tmp/prox_test_deck_XXXXXX");
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    size_t n = strlen(text);
    assert_int_equal(write(fd, text, n), (ssize_t)n);
    close(fd);
}

/* The three numbers of the first JSON array after `key` in s. */
static inline prox_vec3 json_vec_after(const char *s, const char *key)
{
    const char *p = strstr(s, key);
    assert_non_null(p);
    p = strchr(p, '[');
    assert_non_null(p);
    double v[3];
    char *end;
    ++p;
    for (int i = 0; i < 3; ++i) {
        v[i] = strtod(p, &end);
        assert_true(end != p);
        p = end + 1; /* skip the comma */
    }
    return prox_v3(v[0], v[1], v[2]);
}

#endif
