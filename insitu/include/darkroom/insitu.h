/* darkroom/insitu.h: G-buffers captured by a running simulation.
 *
 * A simulation opens a session on a Cinema database, says which cameras and
 * channels it wants, and at each time step it chooses hands over its arrays
 * of points, triangles or line segments with their radii and fields; one
 * call ray traces them for every camera and appends one row per camera to
 * the database (columns: time, then phi and theta or camera). The database
 * is the same as `darkroom capture` writes: `darkroom info` describes it,
 * the editor opens it, pipelines shade it.
 *
 * Arrays are shared with the ray tracer (Embree's shared buffers), not
 * copied, and must stay valid and unchanged until darkroom_insitu_capture
 * returns. Three exceptions, counted by darkroom_insitu_copied_bytes: radii
 * given apart from the positions (Embree wants x, y, z, radius together),
 * positions of lines or points packed closer than 16 bytes, and their
 * records when the array's address or the stride is not a multiple of 16
 * (Embree loads each record with one aligned 16-byte load). Triangles read
 * their x, y, z from records `stride` bytes apart (at least 12); Embree loads
 * 16 bytes at a time, so the last vertex must be followed by 4 readable bytes
 * when the stride is below 16.
 *
 * With MPI (darkroom_insitu_set_mpi_comm), every rank of the communicator
 * hands over its own part; the parts are ray traced where they are and
 * composited by depth, and rank 0 writes. Objects are matched by the order
 * they are declared in, which must be the same on every rank (a rank without
 * a part of an object declares it with no elements). Primitive ids count the
 * ranks' parts in rank order, so the database equals that of one process
 * holding the whole arrays. The calls marked "collective" must be made by
 * every rank.
 *
 * Every function returns DARKROOM_INSITU_OK (0) or an error code; then
 * darkroom_insitu_error() says what went wrong in one line. A failed
 * collective call fails on every rank. Not thread-safe: one thread per session.
 *
 * Every argument is checked (docs/insitu.md, "Arguments"): numbers must be
 * finite, switches 0 or 1, names one line of printable text, counts and
 * strides within the limits given below; a refused call changes nothing.
 * Cameras are ray traced in single precision, so, as in scene files
 * (docs/scene-format.md, "Bounds"), the field of view lies in [0.001,
 * 179.999] degrees, and darkroom_insitu_capture refuses (BAD_INPUT, nothing
 * written) a camera position, target or orbit distance more than 10^6 scene
 * radii from the step's objects, or an orthographic view height not within
 * 10^-6 to 10^6 of their radius: those would abort inside the ray tracer.
 *
 * The setup (image, cameras, channels, half floats) is fixed by the first
 * capture and recorded in the database: changing it afterwards, or resuming
 * a database made with another setup, is refused, naming what differs.
 *
 * Usable from C, C++ and Fortran (module darkroom_insitu, darkroom_insitu.f90).
 * docs/insitu.md has a walk-through; examples/insitu/ a complete mini-app. */
#ifndef DARKROOM_INSITU_H
#define DARKROOM_INSITU_H

#include <stddef.h>
#include <stdint.h>

#if defined(_WIN32)
#define DARKROOM_INSITU_API
#else
#define DARKROOM_INSITU_API __attribute__((visibility("default")))
#endif

#ifdef __cplusplus
extern "C" {
#endif

typedef struct darkroom_insitu darkroom_insitu;

enum darkroom_insitu_status {
    DARKROOM_INSITU_OK = 0,
    DARKROOM_INSITU_FAILED = 1,    /* could not be done (I/O, MPI, the ray tracer) */
    DARKROOM_INSITU_BAD_INPUT = 2  /* the call's arguments are wrong; nothing changed */
};

enum darkroom_insitu_mode {
    DARKROOM_INSITU_CREATE = 0,     /* refuse an existing, non-empty database */
    DARKROOM_INSITU_OVERWRITE = 1,  /* replace it */
    DARKROOM_INSITU_RESUME = 2      /* keep its rows; rows already there are not captured again */
};

enum darkroom_insitu_association { DARKROOM_INSITU_POINT_DATA = 0, DARKROOM_INSITU_CELL_DATA = 1 };

/* A session writing the database folder `database` (e.g. "out/heat.cdb").
 * Never NULL: on failure the session carries the error and every later call
 * fails with it. Nothing is written before the first capture. */
DARKROOM_INSITU_API darkroom_insitu* darkroom_insitu_open(const char* database, int mode);

/* Shares the work with the other ranks of an MPI communicator, given as its
 * Fortran handle: MPI_Comm_c2f(comm) in C, the integer itself in Fortran.
 * Collective; call before the first capture. */
DARKROOM_INSITU_API int darkroom_insitu_set_mpi_comm(darkroom_insitu* s, int fortran_comm);

/* Worker threads of this process, 0 to 4096 (0, the default: the machine's
 * cores, divided among the ranks on the node). */
DARKROOM_INSITU_API int darkroom_insitu_set_threads(darkroom_insitu* s, int threads);

/* Image size (1 to 65536 pixels each way) and projection of every camera:
 * perspective with a vertical field of view in [0.001, 179.999] degrees, or
 * orthographic when fov_degrees is 0 and view_height (world units) is
 * positive; view_height is otherwise 0 or any finite positive number. */
DARKROOM_INSITU_API int darkroom_insitu_set_image(darkroom_insitu* s, int width, int height, double fov_degrees,
                                                 double view_height);

/* Cameras: either an orbit (Cinema's phi/theta grid around `target` at
 * `distance`, `up` the axis of phi; columns phi, theta; the conventions of
 * docs/scene-format.md; 1 to 3600 angles each, phi in [-360, 360], theta in
 * [-90, 90]) or a list of cameras (column camera = 0, 1, ...; up not
 * parallel to the view direction). Directions may have any finite non-zero
 * length. */
DARKROOM_INSITU_API int darkroom_insitu_camera_orbit(darkroom_insitu* s, const double target[3], double distance,
                                                    const double up[3], const double* phi, int phi_count,
                                                    const double* theta, int theta_count);
DARKROOM_INSITU_API int darkroom_insitu_add_camera(darkroom_insitu* s, const double position[3],
                                                  const double target[3], const double up[3]);

/* Channels besides depth (Z, always stored): a field by name (NaN where an
 * object lacks it), geometric normals N.x N.y N.z, object and primitive ids.
 * `on`, `object_ids` and `primitive_ids` are 0 (off) or 1 (on). */
DARKROOM_INSITU_API int darkroom_insitu_request_field(darkroom_insitu* s, const char* name);
DARKROOM_INSITU_API int darkroom_insitu_request_normals(darkroom_insitu* s, int on);
DARKROOM_INSITU_API int darkroom_insitu_request_ids(darkroom_insitu* s, int object_ids, int primitive_ids);
/* Store scalar channels as half floats (depth and ids stay exact). */
DARKROOM_INSITU_API int darkroom_insitu_set_half_float(darkroom_insitu* s, int on);

/* Starts describing the time step `time`: forgets the objects of the last one. */
DARKROOM_INSITU_API int darkroom_insitu_begin_step(darkroom_insitu* s, double time);

/* Objects of this step. `vertices` holds x, y, z (floats) at the start of
 * each record, records `stride` bytes apart (0: 12 for triangles, 16 for
 * lines and points; a multiple of 4 from 12 to 2^31 - 4). Lines and points
 * take their radius from `radii` (one per vertex) when not NULL, else from
 * offset 12 of each record when the stride is at least 16, else the
 * constant `radius` (then positive; otherwise 0 or positive). Radii must be
 * finite and not negative. Counts: 0 to 2^32 - 1.
 * Triangles: 3 vertex indices each. Lines: one index per segment, the
 * segment joining vertex i and i + 1 (a polyline of n vertices is n - 1
 * consecutive indices). Points: every vertex is a sphere. */
DARKROOM_INSITU_API int darkroom_insitu_triangles(darkroom_insitu* s, const char* name, const float* vertices,
                                                 size_t stride, int64_t vertex_count, const uint32_t* triangles,
                                                 int64_t triangle_count);
DARKROOM_INSITU_API int darkroom_insitu_lines(darkroom_insitu* s, const char* name, const float* vertices,
                                             size_t stride, int64_t vertex_count, const uint32_t* segments,
                                             int64_t segment_count, const float* radii, float radius);
DARKROOM_INSITU_API int darkroom_insitu_points(darkroom_insitu* s, const char* name, const float* vertices,
                                              size_t stride, int64_t vertex_count, const float* radii,
                                              float radius);

/* A field of the object `object` declared in this step: one value per
 * vertex (POINT_DATA, interpolated across triangles and segments) or per
 * primitive (CELL_DATA). Shared, not copied. */
DARKROOM_INSITU_API int darkroom_insitu_field(darkroom_insitu* s, const char* object, const char* name,
                                             const float* values, int64_t count, int association);

/* Ray traces this step for every camera and appends its rows (collective).
 * Opens (and locks) the database on the first call. */
DARKROOM_INSITU_API int darkroom_insitu_capture(darkroom_insitu* s);

/* Finishes the database and frees the session (collective); s may be NULL.
 * Returns the first error the session met, if any. */
DARKROOM_INSITU_API int darkroom_insitu_close(darkroom_insitu* s);

/* The last error in one line ("" when none); valid until the next call. */
DARKROOM_INSITU_API const char* darkroom_insitu_error(const darkroom_insitu* s);

/* Bytes of the simulation's arrays copied so far (radii or packing, see above). */
DARKROOM_INSITU_API int64_t darkroom_insitu_copied_bytes(const darkroom_insitu* s);

/* Rows written by this session (on rank 0; 0 elsewhere). */
DARKROOM_INSITU_API int64_t darkroom_insitu_rows_written(const darkroom_insitu* s);

/* For language bindings: makes `message` the session's last error (the
 * Fortran module reports a non-contiguous array this way; control
 * characters become spaces). Returns DARKROOM_INSITU_BAD_INPUT. */
DARKROOM_INSITU_API int darkroom_insitu_report_error(darkroom_insitu* s, const char* message);

#ifdef __cplusplus
}
#endif

#endif /* DARKROOM_INSITU_H */
