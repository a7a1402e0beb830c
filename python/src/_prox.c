/* prox._prox: the C extension behind the Python package prox (docs/python.md).
 *
 * One entry point, query(), answers a whole batch of pairs: the shapes come in as C-contiguous
 * float64 arrays with one shape per row (the layouts of python/prox/_shapes.py), the answers go out
 * as new numpy arrays. The rows are split over pthreads with the GIL released; each row calls the same
 * library function the command-line tool calls for that mode and method (src/cli/pairs.c), so a batch
 * row, a single query and `prox pairs` give the same bits. An invalid row never stops the batch: its
 * status says why and its numbers are NaN. */
#define PY_SSIZE_T_CLEAN
#include <Python.h>
#include <numpy/arrayobject.h>

#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include <gsl/gsl_errno.h>

#include "cli/cli.h"
#include "prox/prox.h"

/* The three questions, as python/prox/_query.py numbers them. */
enum { MODE_DISTANCE = 0, MODE_SIGNED = 1, MODE_TEST = 2 };

/* Doubles per row of each shape kind (indexed by prox_shape_kind): RCC base, axis, radius; BOX corner,
 * three edges; RPP xmin xmax ymin ymax zmin zmax; SPH centre, radius; TRC base, axis, r1, r2; REC base,
 * axis, a1, a2; ELL centre, axis, radius; RHP base, axis, r1, r2, r3; WED vertex, v1, v2, v3; ARB eight
 * corners and six face numbers. */
static const npy_intp row_width[PROX_SHAPE_KIND_COUNT_] = {7, 12, 6, 4, 8, 12, 7, 15, 12, 30};

/* Rows handed to a thread at a time: small enough to balance rows of unequal cost, large enough that
 * the shared counter is touched rarely. */
#define CHUNK_MIN 16
#define CHUNK_MAX 4096
/* Work (ns) that the rest of a batch must hold per extra thread before one is started. */
#define SPAWN_WORK_NS 100000.0
/* Threads of one batch at most, whatever `threads` asks for. */
#define THREADS_MAX 256.0

/* One batch: inputs, outputs and the counter the threads take chunks of rows from. */
typedef struct batch {
    int mode, ka, kb, both_rcc;
    prox_method method;
    const double *a, *b;
    size_t sa, sb; /* row strides in doubles; 0 repeats the single shape of that side */
    size_t n, chunk;
    double *val;   /* distance or signed distance, (n,) */
    double *p1, *p2, *normal; /* (n, 3) */
    npy_bool *intersect, *certified;
    int32_t *status;
    atomic_size_t next;
} batch;

static prox_vec3 v3_at(const double *v) { return prox_v3(v[0], v[1], v[2]); }

static prox_rcc rcc_at(const double *v)
{
    prox_rcc c = {v3_at(v), v3_at(v + 3), v[6]};
    return c;
}

/* The generic shape of kind `kind` stored in row v. */
static prox_shape shape_at(int kind, const double *v)
{
    switch (kind) {
    case PROX_SHAPE_RCC: return prox_shape_from_rcc(rcc_at(v));
    case PROX_SHAPE_BOX: {
        prox_box b = {v3_at(v), {v3_at(v + 3), v3_at(v + 6), v3_at(v + 9)}};
        return prox_shape_from_box(b);
    }
    case PROX_SHAPE_RPP: {
        prox_rpp r = {v[0], v[1], v[2], v[3], v[4], v[5]};
        return prox_shape_from_rpp(r);
    }
    case PROX_SHAPE_TRC: return prox_shape_from_trc((prox_trc){v3_at(v), v3_at(v + 3), v[6], v[7]});
    case PROX_SHAPE_REC: return prox_shape_from_rec((prox_rec){v3_at(v), v3_at(v + 3), v3_at(v + 6), v3_at(v + 9)});
    case PROX_SHAPE_ELL: return prox_shape_from_ell((prox_ell){v3_at(v), v3_at(v + 3), v[6]});
    case PROX_SHAPE_RHP:
        return prox_shape_from_rhp((prox_rhp){v3_at(v), v3_at(v + 3), {v3_at(v + 6), v3_at(v + 9), v3_at(v + 12)}});
    case PROX_SHAPE_WED: return prox_shape_from_wed((prox_wed){v3_at(v), v3_at(v + 3), v3_at(v + 6), v3_at(v + 9)});
    case PROX_SHAPE_ARB: {
        prox_arb a;
        for (int k = 0; k < 8; ++k) a.corner[k] = v3_at(v + 3 * k);
        for (int k = 0; k < 6; ++k) /* a face number that is not a small whole number is no face */
            a.face[k] = v[24 + k] >= 0.0 && v[24 + k] <= 9999.0 && v[24 + k] == floor(v[24 + k]) ? (int)v[24 + k] : -1;
        return prox_shape_from_arb(a);
    }
    default: {
        prox_sph s = {v3_at(v), v[3]};
        return prox_shape_from_sph(s);
    }
    }
}

static void put3(double *dst, size_t i, prox_vec3 v)
{
    dst[3 * i] = v.x;
    dst[3 * i + 1] = v.y;
    dst[3 * i + 2] = v.z;
}

static const prox_vec3 nan3 = {NAN, NAN, NAN};

/* Distance of row i: the chosen cylinder method (as `prox pairs --method M`), else the generic query. */
static void row_distance(batch *B, size_t i, const double *va, const double *vb)
{
    prox_distance_result r;
    if (B->both_rcc) {
        prox_rcc a = rcc_at(va), b = rcc_at(vb);
        r = prox_rcc_distance_ex(&a, &b, B->method);
    } else {
        prox_shape a = shape_at(B->ka, va), b = shape_at(B->kb, vb);
        r = prox_shape_distance(&a, &b);
    }
    int ok = r.status == PROX_OK;
    B->status[i] = (int32_t)r.status;
    B->val[i] = ok ? r.distance : NAN;
    put3(B->p1, i, ok ? r.p1 : nan3);
    put3(B->p2, i, ok ? r.p2 : nan3);
    B->intersect[i] = (npy_bool)(ok && r.intersect);
    B->certified[i] = (npy_bool)(ok && r.certified);
}

/* Signed distance of row i. Cylinder pairs as `prox pairs --signed --method M`: the support method's own
 * signed distance for "support", the library's composition (exact distance when disjoint, support-
 * function depth when overlapping) for the other two. */
static void row_signed(batch *B, size_t i, const double *va, const double *vb)
{
    prox_signed_result r;
    prox_shape a = shape_at(B->ka, va), b = shape_at(B->kb, vb);
    if (!B->both_rcc) r = prox_shape_signed_distance(&a, &b);
    else if (B->method == PROX_METHOD_SUPPORT) r = prox_shape_signed_distance_support(&a, &b);
    else r = prox_rcc_signed_distance(&a.u.rcc, &b.u.rcc);
    int ok = r.status == PROX_OK;
    B->status[i] = (int32_t)r.status;
    B->val[i] = ok ? r.sd : NAN;
    put3(B->normal, i, ok ? r.normal : nan3);
    put3(B->p1, i, ok ? r.p1 : nan3);
    put3(B->p2, i, ok ? r.p2 : nan3);
    B->certified[i] = (npy_bool)(ok && r.certified);
}

/* Intersection verdict of row i. Cylinder pairs as `prox pairs --test --method M`: the separating
 * axes for "support", the chosen distance method's verdict otherwise. */
static void row_test(batch *B, size_t i, const double *va, const double *vb)
{
    prox_status st;
    int hit;
    if (B->both_rcc && B->method != PROX_METHOD_SUPPORT) {
        prox_rcc a = rcc_at(va), b = rcc_at(vb);
        prox_distance_result r = prox_rcc_distance_ex(&a, &b, B->method);
        st = r.status, hit = r.intersect;
    } else if (B->both_rcc) {
        prox_rcc a = rcc_at(va), b = rcc_at(vb);
        prox_test_result r = prox_rcc_sat(&a, &b);
        st = r.status, hit = r.intersect;
    } else {
        prox_shape a = shape_at(B->ka, va), b = shape_at(B->kb, vb);
        prox_test_result r = prox_shape_test(&a, &b);
        st = r.status, hit = r.intersect;
    }
    B->status[i] = (int32_t)st;
    B->intersect[i] = (npy_bool)(st == PROX_OK && hit);
}

/* Answers rows lo..hi-1 of the batch. */
static void run_rows(batch *B, size_t lo, size_t hi)
{
    for (size_t i = lo; i < hi; ++i) {
        const double *va = B->a + i * B->sa, *vb = B->b + i * B->sb;
        if (B->mode == MODE_DISTANCE) row_distance(B, i, va, vb);
        else if (B->mode == MODE_SIGNED) row_signed(B, i, va, vb);
        else row_test(B, i, va, vb);
    }
}

/* A thread's loop: take the next chunk of rows until none is left. */
static void *worker(void *arg)
{
    batch *B = arg;
    for (;;) {
        size_t lo = atomic_fetch_add(&B->next, B->chunk);
        if (lo >= B->n) break;
        run_rows(B, lo, lo + B->chunk < B->n ? lo + B->chunk : B->n);
    }
    return NULL;
}

static double now_ns(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return 1e9 * (double)ts.tv_sec + (double)ts.tv_nsec;
}

/* How many threads the rest of the batch is worth: one per SPAWN_WORK_NS of work left (estimated
 * from the first chunk, which the caller has just answered in first_ns), and no more than `threads`,
 * THREADS_MAX or the chunks left. Starting and joining a thread costs tens of microseconds, more than
 * a small batch of fast rows is worth. */
static int threads_worth(const batch *B, size_t done, double first_ns, int threads)
{
    double left_ns = first_ns / (double)done * (double)(B->n - done);
    double chunks_left = (double)((B->n - done + B->chunk - 1) / B->chunk);
    double cap = fmin(fmin((double)threads, THREADS_MAX), chunks_left);
    return (int)fmin(cap, 1.0 + floor(left_ns / SPAWN_WORK_NS));
}

/* Runs the batch on up to `threads` threads (the caller's among them). Called without the GIL. The
 * caller answers a first chunk alone, to learn what a row costs; a thread that cannot be started
 * leaves its share to the others. */
static void run_batch(batch *B, int threads)
{
    size_t chunk = B->n / (8 * (size_t)threads);
    B->chunk = chunk < CHUNK_MIN ? CHUNK_MIN : chunk > CHUNK_MAX ? CHUNK_MAX : chunk;
    size_t first = B->chunk < B->n ? B->chunk : B->n;
    atomic_init(&B->next, first);
    double t0 = now_ns();
    run_rows(B, 0, first);
    if (first == B->n) return;
    if (threads > 1) threads = threads_worth(B, first, now_ns() - t0, threads);
    pthread_t *tid = threads > 1 ? malloc((size_t)(threads - 1) * sizeof *tid) : NULL;
    int started = 0;
    if (tid)
        for (int t = 0; t < threads - 1; ++t, ++started)
            if (pthread_create(&tid[t], NULL, worker, B) != 0) break;
    worker(B);
    for (int t = 0; t < started; ++t) pthread_join(tid[t], NULL);
    free(tid);
}

/* The shapes of one side as a C-contiguous (N, width) float64 array (a new reference), or NULL with
 * ValueError. */
static PyArrayObject *side_array(PyObject *obj, int kind, const char *name)
{
    if (kind < PROX_SHAPE_RCC || kind >= PROX_SHAPE_KIND_COUNT_) {
        PyErr_Format(PyExc_ValueError, "shape %s: unknown shape kind %d", name, kind);
        return NULL;
    }
    PyArrayObject *arr = (PyArrayObject *)PyArray_FROMANY(obj, NPY_DOUBLE, 2, 2, NPY_ARRAY_IN_ARRAY);
    if (!arr) return NULL;
    if (PyArray_DIM(arr, 1) != row_width[kind]) {
        PyErr_Format(PyExc_ValueError, "shape %s: expected rows of %zd numbers, got %zd", name,
                     (Py_ssize_t)row_width[kind], (Py_ssize_t)PyArray_DIM(arr, 1));
        Py_DECREF(arr);
        return NULL;
    }
    return arr;
}

static PyObject *new_array(int nd, npy_intp n, int type)
{
    npy_intp dims[2] = {n, 3};
    return PyArray_EMPTY(nd, dims, type, 0);
}

/* The output arrays of a mode, as the tuple query() returns. */
static PyObject *make_outputs(batch *B, npy_intp n)
{
    PyObject *val = NULL, *p1 = NULL, *p2 = NULL, *nrm = NULL, *hit = NULL, *cert = NULL, *st = NULL;
    st = new_array(1, n, NPY_INT32);
    if (B->mode != MODE_TEST) {
        val = new_array(1, n, NPY_DOUBLE);
        p1 = new_array(2, n, NPY_DOUBLE);
        p2 = new_array(2, n, NPY_DOUBLE);
    }
    if (B->mode == MODE_SIGNED) nrm = new_array(2, n, NPY_DOUBLE);
    if (B->mode != MODE_SIGNED) hit = new_array(1, n, NPY_BOOL);
    if (B->mode != MODE_TEST) cert = new_array(1, n, NPY_BOOL);
    PyObject *out = NULL;
    if (B->mode == MODE_DISTANCE && val && p1 && p2 && hit && cert && st)
        out = PyTuple_Pack(6, val, p1, p2, hit, cert, st);
    else if (B->mode == MODE_SIGNED && val && nrm && p1 && p2 && cert && st)
        out = PyTuple_Pack(6, val, nrm, p1, p2, cert, st);
    else if (B->mode == MODE_TEST && hit && st) out = PyTuple_Pack(2, hit, st);
    if (out) {
        B->status = PyArray_DATA((PyArrayObject *)st);
        if (val) B->val = PyArray_DATA((PyArrayObject *)val);
        if (p1) B->p1 = PyArray_DATA((PyArrayObject *)p1);
        if (p2) B->p2 = PyArray_DATA((PyArrayObject *)p2);
        if (nrm) B->normal = PyArray_DATA((PyArrayObject *)nrm);
        if (hit) B->intersect = PyArray_DATA((PyArrayObject *)hit);
        if (cert) B->certified = PyArray_DATA((PyArrayObject *)cert);
    }
    Py_XDECREF(val);
    Py_XDECREF(p1);
    Py_XDECREF(p2);
    Py_XDECREF(nrm);
    Py_XDECREF(hit);
    Py_XDECREF(cert);
    Py_XDECREF(st);
    return out;
}

/* Checks the scalar arguments of query(); 0 with ValueError when one is out of range. */
static int check_args(const batch *B, int threads)
{
    if (B->mode < MODE_DISTANCE || B->mode > MODE_TEST)
        return PyErr_Format(PyExc_ValueError, "unknown mode %d", B->mode), 0;
    if (!prox_method_name(B->method)) return PyErr_Format(PyExc_ValueError, "unknown method %d", (int)B->method), 0;
    if (!B->both_rcc && B->method != PROX_METHOD_FAST)
        return PyErr_SetString(PyExc_ValueError, "only cylinder pairs (RCC, RCC) take a method other than \"fast\""), 0;
    if (threads < 1) return PyErr_SetString(PyExc_ValueError, "threads must be at least 1"), 0;
    return 1;
}

PyDoc_STRVAR(query_doc, "query(kind_a, a, kind_b, b, mode, method, threads) -> tuple of arrays\n\n"
                        "Answers every row pair (N vs N, 1 vs N or N vs 1). mode 0 distance -> (distance, p1, p2,\n"
                        "intersect, certified, status); 1 signed -> (sd, normal, p1, p2, certified, status); 2 test ->\n"
                        "(intersect, status). The GIL is released while the rows run on `threads` threads.");

static PyObject *py_query(PyObject *self, PyObject *args)
{
    (void)self;
    PyObject *oa, *ob;
    int ka, kb, mode, method, threads;
    if (!PyArg_ParseTuple(args, "iOiOiii", &ka, &oa, &kb, &ob, &mode, &method, &threads)) return NULL;
    batch B = {.mode = mode, .ka = ka, .kb = kb, .method = (prox_method)method};
    B.both_rcc = ka == PROX_SHAPE_RCC && kb == PROX_SHAPE_RCC;
    if (!check_args(&B, threads)) return NULL;
    PyArrayObject *aa = side_array(oa, ka, "A"), *ab = aa ? side_array(ob, kb, "B") : NULL;
    if (!ab) {
        Py_XDECREF(aa);
        return NULL;
    }
    npy_intp na = PyArray_DIM(aa, 0), nb = PyArray_DIM(ab, 0);
    PyObject *out = NULL;
    if (na != nb && na != 1 && nb != 1) {
        PyErr_Format(PyExc_ValueError, "cannot pair %zd shapes with %zd (N vs N, 1 vs N or N vs 1)", (Py_ssize_t)na,
                     (Py_ssize_t)nb);
        goto done;
    }
    npy_intp n = na == 1 ? nb : na;
    B.a = PyArray_DATA(aa), B.b = PyArray_DATA(ab), B.n = (size_t)n;
    B.sa = na == 1 ? 0 : (size_t)row_width[ka];
    B.sb = nb == 1 ? 0 : (size_t)row_width[kb];
    out = make_outputs(&B, n);
    if (!out || n == 0) goto done;
    Py_BEGIN_ALLOW_THREADS
    run_batch(&B, threads);
    Py_END_ALLOW_THREADS
done:
    Py_DECREF(aa);
    Py_DECREF(ab);
    return out;
}

PyDoc_STRVAR(validate_doc, "validate(kind, rows) -> int32 array\n\n"
                           "prox_shape_validate of each row: the status a query would report for that shape.");

static PyObject *py_validate(PyObject *self, PyObject *args)
{
    (void)self;
    PyObject *obj;
    int kind;
    if (!PyArg_ParseTuple(args, "iO", &kind, &obj)) return NULL;
    PyArrayObject *arr = side_array(obj, kind, "rows");
    if (!arr) return NULL;
    npy_intp n = PyArray_DIM(arr, 0);
    PyObject *out = new_array(1, n, NPY_INT32);
    if (out) {
        const double *v = PyArray_DATA(arr);
        int32_t *st = PyArray_DATA((PyArrayObject *)out);
        for (npy_intp i = 0; i < n; ++i) {
            prox_shape s = shape_at(kind, v + (size_t)i * (size_t)row_width[kind]);
            st[i] = (int32_t)prox_shape_validate(&s);
        }
    }
    Py_DECREF(arr);
    return out;
}

PyDoc_STRVAR(check_doc, "check_deck(path, clearance, all, bodies, resolution, strict, threads) -> (report or None,\n"
                        "exit status, prox status)\n\n"
                        "The JSON report of `prox check DECK --json` with those options (src/cli/check.c), as text.");

static PyObject *py_check_deck(PyObject *self, PyObject *args)
{
    (void)self;
    const char *path;
    double clearance, resolution;
    int all, bodies, strict, threads;
    if (!PyArg_ParseTuple(args, "sdppdpi", &path, &clearance, &all, &bodies, &resolution, &strict, &threads)) return NULL;
    if (!(clearance >= 0.0) || isinf(clearance)) return PyErr_Format(PyExc_ValueError, "clearance must be finite and >= 0");
    if (!(resolution >= 0.0) || isinf(resolution))
        return PyErr_Format(PyExc_ValueError, "resolution must be finite and >= 0 (0: the default)");
    if (threads < 0) return PyErr_Format(PyExc_ValueError, "threads must be >= 0 (0: the default)");
    prox_check_args opts = {.path = path, .clearance = clearance, .all = all, .json = 1, .bodies = bodies,
                            .strict = strict, .resolution = resolution, .threads = threads};
    char *text = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&text, &len);
    if (!f) return PyErr_NoMemory();
    prox_status st = PROX_OK;
    int code;
    Py_BEGIN_ALLOW_THREADS
    code = prox_check_run(&opts, f, &st);
    Py_END_ALLOW_THREADS
    fclose(f);
    PyObject *report = Py_None;
    if (st == PROX_OK) report = PyUnicode_DecodeUTF8(text, (Py_ssize_t)len, "replace");
    else Py_INCREF(report);
    free(text);
    if (!report) return NULL;
    return Py_BuildValue("Nii", report, code, (int)st);
}

static PyObject *py_version(PyObject *self, PyObject *noargs)
{
    (void)self, (void)noargs;
    return PyUnicode_FromString(prox_version());
}

static PyObject *py_status_str(PyObject *self, PyObject *arg)
{
    (void)self;
    long code = PyLong_AsLong(arg);
    if (code == -1 && PyErr_Occurred()) return NULL;
    return PyUnicode_FromString(prox_status_str((prox_status)code));
}

static PyObject *py_method_code(PyObject *self, PyObject *arg)
{
    (void)self;
    const char *name = PyUnicode_AsUTF8(arg);
    prox_method m;
    if (!name) return NULL;
    if (!prox_method_parse(name, &m)) return PyErr_Format(PyExc_ValueError, "unknown method '%s'", name);
    return PyLong_FromLong((long)m);
}

static PyMethodDef methods[] = {
    {"query", py_query, METH_VARARGS, query_doc},
    {"check_deck", py_check_deck, METH_VARARGS, check_doc},
    {"validate", py_validate, METH_VARARGS, validate_doc},
    {"version", py_version, METH_NOARGS, "prox_version() of the C library."},
    {"status_str", py_status_str, METH_O, "prox_status_str(code): the text of a status code."},
    {"method_code", py_method_code, METH_O, "The prox_method value of a method name (ValueError if unknown)."},
    {NULL, NULL, 0, NULL},
};

static struct PyModuleDef module = {PyModuleDef_HEAD_INIT, "_prox", "C extension of prox (docs/python.md).", -1,
                                    methods, NULL, NULL, NULL, NULL};

/* Adds the status codes as integer constants STATUS_<NAME>. */
static int add_status_codes(PyObject *m)
{
    static const struct { const char *name; prox_status code; } codes[] = {
        {"OK", PROX_OK}, {"EINVAL_NONFINITE", PROX_EINVAL_NONFINITE}, {"EINVAL_RADIUS", PROX_EINVAL_RADIUS},
        {"EINVAL_AXIS", PROX_EINVAL_AXIS}, {"EINVAL_BOX_EDGE", PROX_EINVAL_BOX_EDGE},
        {"EINVAL_BOX_ORTHO", PROX_EINVAL_BOX_ORTHO}, {"EINVAL_RPP_BOUNDS", PROX_EINVAL_RPP_BOUNDS},
        {"EINVAL_ARG", PROX_EINVAL_ARG}, {"EINVAL_RANGE", PROX_EINVAL_RANGE},
        {"EINVAL_SHAPE_KIND", PROX_EINVAL_SHAPE_KIND}, {"ENUMERIC", PROX_ENUMERIC}, {"ENOMEM", PROX_ENOMEM},
        {"EUNSUPPORTED", PROX_EUNSUPPORTED}, {"EINVAL_TRC", PROX_EINVAL_TRC},
        {"EINVAL_REC_ORTHO", PROX_EINVAL_REC_ORTHO}, {"EINVAL_ELL", PROX_EINVAL_ELL},
        {"EINVAL_RHP", PROX_EINVAL_RHP}, {"EINVAL_WED", PROX_EINVAL_WED},
        {"EINVAL_ARB_FACE", PROX_EINVAL_ARB_FACE}, {"EINVAL_ARB_PLANAR", PROX_EINVAL_ARB_PLANAR},
        {"EINVAL_ARB_CONVEX", PROX_EINVAL_ARB_CONVEX},
    };
    _Static_assert(sizeof codes / sizeof codes[0] == PROX_STATUS_COUNT_, "every prox_status has its constant");
    for (size_t i = 0; i < sizeof codes / sizeof codes[0]; ++i) {
        char name[64];
        snprintf(name, sizeof name, "STATUS_%s", codes[i].name);
        if (PyModule_AddIntConstant(m, name, (long)codes[i].code) < 0) return -1;
    }
    return PyModule_AddIntConstant(m, "STATUS_COUNT", (long)PROX_STATUS_COUNT_);
}

PyMODINIT_FUNC PyInit__prox(void);

PyMODINIT_FUNC PyInit__prox(void)
{
    import_array();
    /* GSL's default handler aborts the process; the library checks every GSL status itself. */
    gsl_set_error_handler_off();
    PyObject *m = PyModule_Create(&module);
    if (!m) return NULL;
    if (add_status_codes(m) < 0) {
        Py_DECREF(m);
        return NULL;
    }
    return m;
}
