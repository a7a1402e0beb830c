/* Reproducible stress driver for the three fuzz harnesses (fuzz_queries.c, fuzz_deck.c, fuzz_pairs.c).
 *
 * libFuzzer's coverage feedback makes its input sequence depend on the machine: the same -seed tries
 * other inputs wherever a floating-point result (libm picks CPU-dependent code paths) steers another
 * branch. This driver uses no feedback at all. From a seed, a splitmix64 generator picks a corpus file
 * and applies 1-5 mutations (bit flips, bytes, special and rescaled doubles at the harness's 8-byte
 * slots, insertions, erasures, splices of another corpus file, deck words), so
 * `stress_<name> CORPUS_DIR RUNS SEED CRASH_DIR` tries the same inputs on every machine.
 *
 * Any fault (a broken contract's trap, a sanitizer report, a crash, a hang of 10 s) writes the input
 * to CRASH_DIR/stress-<seed>-<index> and exits 1; `stress_<name> FILE...` replays files with the
 * harness's own output, which names the broken contract. The harness's output is silenced while
 * stressing (the pairs harness runs the CLI, which prints every answer). */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <sanitizer/common_interface_defs.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerInitialize(int *argc, char ***argv);

/* Inputs are at most this long, like run.sh's -max_len. */
#define STRESS_MAX_LEN 4096
/* Seconds an input may take before it counts as a hang (run.sh's -timeout). */
#define STRESS_TIMEOUT 10

typedef struct {
    uint8_t *data;
    size_t size;
} unit;

static uint64_t rng_state;

/* splitmix64: a fixed sequence from the seed, the same on every machine. */
static uint64_t rng(void)
{
    uint64_t z = (rng_state += 0x9E3779B97F4A7C15u);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9u;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBu;
    return z ^ (z >> 31);
}

static size_t below(size_t n) { return n ? (size_t)(rng() % n) : 0; }

/* The input under test, for the fault handlers (async-signal-safe writes only). */
static uint8_t cur[STRESS_MAX_LEN];
static size_t cur_size;
static char crash_path[4096];
static int saved_err = 2;

static void say(const char *s) { (void)!write(saved_err, s, strlen(s)); }

static void dump_and_exit(const char *what)
{
    int fd = open(crash_path, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) {
        (void)!write(fd, cur, cur_size);
        close(fd);
    }
    say("stress: ");
    say(what);
    say("; input written to ");
    say(crash_path);
    say("\n");
    _exit(1);
}

static void on_signal(int sig)
{
    dump_and_exit(sig == SIGALRM ? "hang" : "fatal signal (a broken contract traps)");
}

static int finished;

static void on_death(void)
{
    if (finished) {
        say("stress: a sanitizer report at exit (a leak: replay the inputs to find the one)\n");
        _exit(1);
    }
    dump_and_exit("sanitizer report");
}

static int cmp_names(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

static int read_file(const char *path, unit *u)
{
    FILE *f = fopen(path, "rb");
    if (!f) return 0;
    u->data = malloc(STRESS_MAX_LEN);
    u->size = u->data ? fread(u->data, 1, STRESS_MAX_LEN, f) : 0;
    fclose(f);
    return u->data != NULL;
}

/* The corpus files in name order (readdir's order is the file system's). */
static size_t load_corpus(const char *dir, unit **out)
{
    DIR *d = opendir(dir);
    if (!d) return 0;
    char **names = NULL;
    size_t n = 0;
    for (struct dirent *e; (e = readdir(d));) {
        if (e->d_name[0] == '.') continue;
        names = realloc(names, (n + 1) * sizeof *names);
        names[n++] = strdup(e->d_name);
    }
    closedir(d);
    qsort(names, n, sizeof *names, cmp_names);
    unit *units = calloc(n ? n : 1, sizeof *units);
    size_t m = 0;
    for (size_t i = 0; i < n; ++i) {
        char path[4096];
        snprintf(path, sizeof path, "%s/%s", dir, names[i]);
        if (read_file(path, &units[m])) ++m;
        free(names[i]);
    }
    free(names);
    *out = units;
    return m;
}

/* Doubles that reach the solvers' edge cases: zeros, units, the ends of the range, subnormals. */
static double special_double(void)
{
    static const double table[] = {0.0, -0.0, 1.0, -1.0, 0.5, 2.0, 1e-300, 1e300, 2.2250738585072014e-308,
                                   4.9406564584124654e-324, 1.7976931348623157e308, 1e-12, 1e12, 1e-9,
                                   3.0, 10.0};
    size_t k = below(sizeof table / sizeof table[0] + 3);
    if (k < sizeof table / sizeof table[0]) return table[k];
    if (k == sizeof table / sizeof table[0]) return (double)(int64_t)rng() / 9.2e18 * 20.0;
    double x = (double)(rng() >> 11) / 9007199254740992.0;
    int e = (int)below(2 * 330) - 330;
    double p = 1.0;
    for (int i = 0; i < (e < 0 ? -e : e); ++i) p *= e < 0 ? 0.1 : 10.0;
    return (rng() & 1 ? -x : x) * p;
}

/* An 8-byte slot of the harnesses' raw doubles (payload from byte 1 or 2). */
static size_t slot(size_t size)
{
    if (size < 10) return 0;
    size_t base = 1 + below(2);
    return base + 8 * below((size - base) / 8);
}

static const char *const words[] = {"RCC", "BOX", "RPP", "SPH", "TRC", "REC", "ELL", "WED", "RHP", "HEX",
                                    "ARB", "like", "but", "trcl=", "fill=", "u=", "imp:n=1", "*", "#",
                                    "(", ")", ":", " -", "\n", "\n\n", "&", "c ", "$", "1e300", "-0",
                                    "nan", "1e-300", "0", " 1 ", "j", "2r", "3i", "m"};

static void mutate_once(uint8_t *b, size_t *n, const unit *corpus, size_t ncorpus)
{
    size_t size = *n;
    switch (below(size ? 9 : 1) + (size ? 0 : 5)) {
    case 0: /* flip a bit */
        b[below(size)] ^= (uint8_t)(1u << below(8));
        break;
    case 1: /* set a byte */
        b[below(size)] = (uint8_t)rng();
        break;
    case 2: /* a special double in a slot */
    case 3: {
        size_t at = slot(size);
        if (at + 8 <= size) {
            double x = special_double();
            memcpy(b + at, &x, 8);
        }
        break;
    }
    case 4: { /* rescale a double by 2^k */
        size_t at = slot(size);
        if (at + 8 <= size) {
            double x;
            memcpy(&x, b + at, 8);
            int k = (int)below(2 * 64) - 64;
            if (rng() % 8 == 0) k *= 16;
            for (int i = 0; i < (k < 0 ? -k : k); ++i) x *= k < 0 ? 0.5 : 2.0;
            memcpy(b + at, &x, 8);
        }
        break;
    }
    case 5: { /* insert a deck word or random bytes */
        uint8_t tmp[16];
        size_t len;
        if (rng() & 1) {
            const char *w = words[below(sizeof words / sizeof words[0])];
            len = strlen(w);
            memcpy(tmp, w, len);
        } else {
            len = 1 + below(16);
            for (size_t i = 0; i < len; ++i) tmp[i] = (uint8_t)rng();
        }
        if (size + len > STRESS_MAX_LEN) break;
        size_t at = below(size + 1);
        memmove(b + at + len, b + at, size - at);
        memcpy(b + at, tmp, len);
        *n = size + len;
        break;
    }
    case 6: { /* erase a range */
        size_t at = below(size), len = 1 + below(size - at < 16 ? size - at : 16);
        memmove(b + at, b + at + len, size - at - len);
        *n = size - len;
        break;
    }
    case 7: { /* copy a range within the input */
        size_t from = below(size), to = below(size), len = 1 + below(32);
        if (from + len > size) len = size - from;
        if (to + len > size) len = size - to;
        memmove(b + to, b + from, len);
        break;
    }
    default: { /* splice a range of another corpus file over the same place */
        const unit *o = &corpus[below(ncorpus)];
        if (!o->size) break;
        size_t at = below(o->size), len = 1 + below(o->size - at);
        if (at + len > STRESS_MAX_LEN) len = STRESS_MAX_LEN - at;
        memcpy(b + at, o->data + at, len);
        if (at + len > size) *n = at + len;
        break;
    }
    }
}

static int replay(int argc, char **argv)
{
    for (int i = 1; i < argc; ++i) {
        unit u;
        if (!read_file(argv[i], &u)) {
            fprintf(stderr, "stress: cannot read %s\n", argv[i]);
            return 2;
        }
        fprintf(stderr, "stress: replaying %s (%zu bytes)\n", argv[i], u.size);
        LLVMFuzzerTestOneInput(u.data, u.size);
        free(u.data);
    }
    return 0;
}

int main(int argc, char **argv)
{
    LLVMFuzzerInitialize(&argc, &argv);
    if (argc != 5) return replay(argc, argv);
    unit *corpus = NULL;
    size_t ncorpus = load_corpus(argv[1], &corpus);
    long runs = atol(argv[2]);
    rng_state = strtoull(argv[3], NULL, 10);
    if (!ncorpus || runs < 0) {
        fprintf(stderr, "usage: %s CORPUS_DIR RUNS SEED CRASH_DIR | %s FILE...\n", argv[0], argv[0]);
        return 2;
    }
    /* Keep a way to report, then silence the harness. */
    saved_err = dup(2);
    int null = open("/dev/null", O_WRONLY);
    dup2(null, 1);
    dup2(null, 2);
    signal(SIGILL, on_signal);
    signal(SIGSEGV, on_signal);
    signal(SIGBUS, on_signal);
    signal(SIGFPE, on_signal);
    signal(SIGABRT, on_signal);
    signal(SIGALRM, on_signal);
    __sanitizer_set_death_callback(on_death);
    for (long i = 0; i < runs; ++i) {
        const unit *u = &corpus[below(ncorpus)];
        memcpy(cur, u->data, u->size);
        cur_size = u->size;
        for (size_t m = 1 + below(5); m > 0; --m) mutate_once(cur, &cur_size, corpus, ncorpus);
        snprintf(crash_path, sizeof crash_path, "%s/stress-%s-%ld", argv[4], argv[3], i);
        /* The harness gets a copy of exactly its size, so that ASan sees reads beyond the end. */
        uint8_t *copy = malloc(cur_size ? cur_size : 1);
        memcpy(copy, cur, cur_size);
        alarm(STRESS_TIMEOUT);
        LLVMFuzzerTestOneInput(copy, cur_size);
        alarm(0);
        free(copy);
    }
    for (size_t k = 0; k < ncorpus; ++k) free(corpus[k].data);
    free(corpus);
    finished = 1;
    dup2(saved_err, 2);
    char msg[128];
    snprintf(msg, sizeof msg, "stress: %ld inputs from seed %s, no fault\n", runs, argv[3]);
    say(msg);
    return 0;
}
