/* A small simulation with in situ capture: heat carried round by a swirling
 * flow on the plate [-1, 1]^2, with tracer particles, split over MPI ranks
 * by bands of grid rows. Every few steps it hands its arrays to Darkroom's in
 * situ API, which writes three time-varying Cinema databases laid out like
 * the demo's (docs/examples/demo/): surface.cdb (the temperature as a height
 * field, channel `height`), flow.cdb (each tracer's recent path as a tube,
 * channel `time`) and particles.cdb (the tracers as spheres, channel
 * `value`), with the demo's cameras, so docs/examples/demo.yaml shades them
 * (README.md here).
 *
 *   mpirun -np 4 heat_advection OUTDIR [--size N] [--steps N] [--every N] [--image PIXELS]
 *
 * The arithmetic of every grid cell and tracer does not depend on how the
 * work is split, so any number of ranks writes the same databases byte for
 * byte (examples/insitu/CMakeLists.txt tests 1 against 4 ranks). */
#include <darkroom/insitu.h>

#include <math.h>
#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { kTrail = 12 };               /* positions kept per tracer path */
static const double kDiffusion = 0.002;
static const double kDt = 0.01;

typedef struct {
    int rank, size;
    int n;              /* grid points per side */
    int row0, row1;     /* this rank's rows [row0, row1) */
    double* t;          /* temperature, rows row0 - 1 .. row1 (with halos) */
    double* next;
    int tracer0, tracer1, tracers; /* this rank's tracers [tracer0, tracer1) of tracers */
    double* path;       /* per local tracer: kTrail x, y positions, newest last */
    double* pathTime;   /* per local tracer: kTrail times */
    int filled;         /* positions in the paths so far */
} Sim;

static double coord(const Sim* s, int i) { return -1.0 + 2.0 * i / (s->n - 1); }

/* A vortex whose angular speed falls off with the distance from the centre,
 * so the flow shears the warm blobs into spirals. */
static void velocity(double x, double y, double* u, double* v) {
    const double omega = 2.5 * exp(-2.0 * (x * x + y * y));
    *u = -omega * y;
    *v = omega * x;
}

static double* row(const Sim* s, double* field, int j) { return field + (size_t)(j - s->row0 + 1) * (size_t)s->n; }

static void init(Sim* s) {
    const int n = s->n;
    s->t = calloc((size_t)(s->row1 - s->row0 + 2) * (size_t)n, sizeof(double));
    s->next = calloc((size_t)(s->row1 - s->row0 + 2) * (size_t)n, sizeof(double));
    for (int j = s->row0; j < s->row1; ++j)
        for (int i = 0; i < n; ++i) {
            const double x = coord(s, i), y = coord(s, j);
            const double a = exp(-30.0 * ((x - 0.45) * (x - 0.45) + y * y));
            const double b = 0.7 * exp(-40.0 * ((x + 0.3) * (x + 0.3) + (y - 0.35) * (y - 0.35)));
            row(s, s->t, j)[i] = a + b;
        }
    const int count = s->tracer1 - s->tracer0;
    s->path = calloc((size_t)count * kTrail * 2, sizeof(double));
    s->pathTime = calloc((size_t)count * kTrail, sizeof(double));
    for (int k = 0; k < count; ++k) {
        /* Seeds on a spiral, from the tracer's global id only. */
        const int id = s->tracer0 + k;
        const double r = 0.15 + 0.7 * (id + 0.5) / s->tracers, angle = 2.399963 * id;
        s->path[2 * kTrail * k + 2 * (kTrail - 1)] = r * cos(angle);
        s->path[2 * kTrail * k + 2 * (kTrail - 1) + 1] = r * sin(angle);
    }
    s->filled = 1;
}

/* Rows row0 - 1 and row1 from the neighbours (zero beyond the plate). */
static void exchangeHalos(Sim* s) {
    const int n = s->n, below = s->rank > 0 ? s->rank - 1 : MPI_PROC_NULL;
    const int above = s->rank + 1 < s->size ? s->rank + 1 : MPI_PROC_NULL;
    MPI_Sendrecv(row(s, s->t, s->row0), n, MPI_DOUBLE, below, 1, row(s, s->t, s->row1), n, MPI_DOUBLE, above, 1,
                 MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    MPI_Sendrecv(row(s, s->t, s->row1 - 1), n, MPI_DOUBLE, above, 2, row(s, s->t, s->row0 - 1), n, MPI_DOUBLE, below, 2,
                 MPI_COMM_WORLD, MPI_STATUS_IGNORE);
}

/* One explicit step: first-order upwind advection plus diffusion; the
 * plate's edge is held at zero. */
static void step(Sim* s, double time) {
    const int n = s->n;
    const double h = 2.0 / (n - 1);
    exchangeHalos(s);
    for (int j = s->row0; j < s->row1; ++j) {
        const double *c = row(s, s->t, j), *dn = row(s, s->t, j - 1), *up = row(s, s->t, j + 1);
        double* out = row(s, s->next, j);
        for (int i = 0; i < n; ++i) {
            if (i == 0 || i == n - 1 || j == 0 || j == n - 1) {
                out[i] = 0.0;
                continue;
            }
            double u, v;
            velocity(coord(s, i), coord(s, j), &u, &v);
            const double dx = u > 0 ? c[i] - c[i - 1] : c[i + 1] - c[i];
            const double dy = v > 0 ? c[i] - dn[i] : up[i] - c[i];
            const double lap = c[i - 1] + c[i + 1] + dn[i] + up[i] - 4.0 * c[i];
            out[i] = c[i] - kDt / h * (u * dx + v * dy) + kDiffusion * kDt / (h * h) * lap;
        }
    }
    double* swap = s->t;
    s->t = s->next;
    s->next = swap;
    /* Tracers: midpoint rule on the analytic flow; the path shifts by one. */
    for (int k = 0; k < s->tracer1 - s->tracer0; ++k) {
        double* p = s->path + 2 * kTrail * k;
        double* pt = s->pathTime + kTrail * k;
        memmove(p, p + 2, sizeof(double) * 2 * (kTrail - 1));
        memmove(pt, pt + 1, sizeof(double) * (kTrail - 1));
        const double x = p[2 * (kTrail - 2)], y = p[2 * (kTrail - 2) + 1];
        double u, v, um, vm;
        velocity(x, y, &u, &v);
        velocity(x + 0.5 * kDt * u, y + 0.5 * kDt * v, &um, &vm);
        p[2 * (kTrail - 1)] = x + kDt * um;
        p[2 * (kTrail - 1) + 1] = y + kDt * vm;
        pt[kTrail - 1] = time;
    }
    if (s->filled < kTrail) ++s->filled;
}

/* The arrays handed over; they must stay put until the capture returns. */
typedef struct {
    float* surface;          /* x, y, z, 0 per grid point of rows row0 .. min(row1, n - 1) */
    float* height;
    uint32_t* triangles;
    float* tubes;            /* x, y, z, radius per path point */
    float* tubeTime;
    uint32_t* segments;
    float* spheres;          /* x, y, z, radius per tracer */
    float* value;
} Arrays;

static void check(darkroom_insitu* db, int status) {
    if (status == DARKROOM_INSITU_OK) return;
    fprintf(stderr, "heat_advection: %s\n", darkroom_insitu_error(db));
    MPI_Abort(MPI_COMM_WORLD, status);
}

static void handOver(Sim* s, Arrays* a, darkroom_insitu* surface, darkroom_insitu* flow,
                     darkroom_insitu* particles, double time) {
    const int n = s->n;
    /* The surface covers this rank's rows and the first row of the next, so
     * the bands join without a gap: that row must be the neighbour's now. */
    exchangeHalos(s);
    const int last = s->row1 < n ? s->row1 : n - 1;
    const int rows = last - s->row0 + 1;
    for (int j = s->row0; j <= last; ++j)
        for (int i = 0; i < n; ++i) {
            const size_t k = (size_t)(j - s->row0) * (size_t)n + (size_t)i;
            const float z = (float)(0.35 * row(s, s->t, j)[i]);
            a->surface[4 * k] = (float)coord(s, i);
            a->surface[4 * k + 1] = (float)coord(s, j);
            a->surface[4 * k + 2] = z;
            a->surface[4 * k + 3] = 0.0f;
            a->height[k] = z;
        }
    size_t t = 0;
    for (int j = 0; j + 1 < rows; ++j)
        for (int i = 0; i + 1 < n; ++i) {
            const uint32_t v = (uint32_t)(j * n + i);
            const uint32_t quad[6] = {v, v + 1, v + (uint32_t)n + 1, v, v + (uint32_t)n + 1, v + (uint32_t)n};
            memcpy(a->triangles + 6 * t++, quad, sizeof quad);
        }
    check(surface, darkroom_insitu_begin_step(surface, time));
    check(surface, darkroom_insitu_triangles(surface, "plate", a->surface, 16, (int64_t)rows * n, a->triangles,
                                             (int64_t)(2 * t)));
    check(surface, darkroom_insitu_field(surface, "plate", "height", a->height, (int64_t)rows * n,
                                         DARKROOM_INSITU_POINT_DATA));

    const int count = s->tracer1 - s->tracer0, shown = s->filled;
    size_t segs = 0;
    for (int k = 0; k < count; ++k) {
        for (int m = 0; m < shown; ++m) {
            const int q = kTrail - shown + m;
            const size_t o = (size_t)k * (size_t)shown + (size_t)m;
            const double x = s->path[2 * kTrail * k + 2 * q], y = s->path[2 * kTrail * k + 2 * q + 1];
            a->tubes[4 * o] = (float)x;
            a->tubes[4 * o + 1] = (float)y;
            a->tubes[4 * o + 2] = 0.45f;
            a->tubes[4 * o + 3] = 0.012f;
            a->tubeTime[o] = (float)s->pathTime[kTrail * k + q];
            if (m + 1 < shown) a->segments[segs++] = (uint32_t)o;
        }
        const double x = s->path[2 * kTrail * k + 2 * (kTrail - 1)], y = s->path[2 * kTrail * k + 2 * (kTrail - 1) + 1];
        a->spheres[4 * k] = (float)x;
        a->spheres[4 * k + 1] = (float)y;
        a->spheres[4 * k + 2] = 0.45f;
        a->spheres[4 * k + 3] = 0.03f;
        a->value[k] = (float)sqrt(x * x + y * y);
    }
    check(flow, darkroom_insitu_begin_step(flow, time));
    check(flow, darkroom_insitu_lines(flow, "paths", a->tubes, 16, (int64_t)count * shown, a->segments,
                                      (int64_t)segs, NULL, 0.0f));
    check(flow, darkroom_insitu_field(flow, "paths", "time", a->tubeTime, (int64_t)count * shown,
                                      DARKROOM_INSITU_POINT_DATA));
    check(particles, darkroom_insitu_begin_step(particles, time));
    check(particles, darkroom_insitu_points(particles, "tracers", a->spheres, 16, count, NULL, 0.0f));
    check(particles, darkroom_insitu_field(particles, "tracers", "value", a->value, count, DARKROOM_INSITU_POINT_DATA));
}

/* One database with the demo's cameras and one channel. */
static darkroom_insitu* openDatabase(const char* folder, const char* name, const char* field, int pixels) {
    char path[4096];
    snprintf(path, sizeof path, "%s/%s.cdb", folder, name);
    darkroom_insitu* db = darkroom_insitu_open(path, DARKROOM_INSITU_OVERWRITE);
    const double target[3] = {0, 0, 0}, up[3] = {0, 0, 1};
    const double phi[] = {0, 45, 90, 135}, theta[] = {15, 40};
    check(db, darkroom_insitu_set_mpi_comm(db, (int)MPI_Comm_c2f(MPI_COMM_WORLD)));
    check(db, darkroom_insitu_set_image(db, pixels, pixels, 30.0, 0.0));
    check(db, darkroom_insitu_camera_orbit(db, target, 4.6, up, phi, 4, theta, 2));
    check(db, darkroom_insitu_request_field(db, field));
    return db;
}

int main(int argc, char** argv) {
    MPI_Init(&argc, &argv);
    Sim s = {0};
    MPI_Comm_rank(MPI_COMM_WORLD, &s.rank);
    MPI_Comm_size(MPI_COMM_WORLD, &s.size);
    const char* out = NULL;
    int steps = 60, every = 20, pixels = 256;
    s.n = 96;
    s.tracers = 120;
    for (int i = 1; i < argc; ++i) {
        if (i + 1 < argc && strcmp(argv[i], "--size") == 0) s.n = atoi(argv[++i]);
        else if (i + 1 < argc && strcmp(argv[i], "--steps") == 0) steps = atoi(argv[++i]);
        else if (i + 1 < argc && strcmp(argv[i], "--every") == 0) every = atoi(argv[++i]);
        else if (i + 1 < argc && strcmp(argv[i], "--image") == 0) pixels = atoi(argv[++i]);
        else if (argv[i][0] != '-' && !out) out = argv[i];
        else out = NULL, i = argc;
    }
    if (!out || s.n < 8 || steps < 0 || every < 1 || pixels < 8 || s.n < 2 * s.size) {
        if (s.rank == 0)
            fprintf(stderr, "usage: mpirun -np N %s OUTDIR [--size N >= 8 and >= 2 x ranks] [--steps N] [--every N] "
                            "[--image PIXELS]\n", argv[0]);
        MPI_Finalize();
        return 2;
    }
    s.row0 = (int)((long long)s.n * s.rank / s.size);
    s.row1 = (int)((long long)s.n * (s.rank + 1) / s.size);
    s.tracer0 = (int)((long long)s.tracers * s.rank / s.size);
    s.tracer1 = (int)((long long)s.tracers * (s.rank + 1) / s.size);
    init(&s);

    const size_t points = (size_t)(s.row1 - s.row0 + 1) * (size_t)s.n, tracers = (size_t)(s.tracer1 - s.tracer0);
    Arrays a;
    a.surface = calloc(4 * points, sizeof(float));
    a.height = calloc(points, sizeof(float));
    a.triangles = calloc(6 * points, sizeof(uint32_t));
    a.tubes = calloc(4 * tracers * kTrail, sizeof(float));
    a.tubeTime = calloc(tracers * kTrail, sizeof(float));
    a.segments = calloc(tracers * kTrail, sizeof(uint32_t));
    a.spheres = calloc(4 * tracers + 4, sizeof(float));
    a.value = calloc(tracers + 1, sizeof(float));
    darkroom_insitu* surface = openDatabase(out, "surface", "height", pixels);
    darkroom_insitu* flow = openDatabase(out, "flow", "time", pixels);
    darkroom_insitu* particles = openDatabase(out, "particles", "value", pixels);

    double time = 0.0;
    for (int k = 0; k <= steps; ++k) {
        if (k % every == 0) {
            handOver(&s, &a, surface, flow, particles, time);
            check(surface, darkroom_insitu_capture(surface));
            check(flow, darkroom_insitu_capture(flow));
            check(particles, darkroom_insitu_capture(particles));
            if (s.rank == 0) printf("heat_advection: step %d, time %.2f captured\n", k, time);
        }
        if (k < steps) {
            time = (k + 1) * kDt;
            step(&s, time);
        }
    }
    check(surface, darkroom_insitu_close(surface));
    check(flow, darkroom_insitu_close(flow));
    check(particles, darkroom_insitu_close(particles));
    free(a.surface), free(a.height), free(a.triangles), free(a.tubes), free(a.tubeTime), free(a.segments);
    free(a.spheres), free(a.value), free(s.t), free(s.next), free(s.path), free(s.pathTime);
    MPI_Finalize();
    return 0;
}
