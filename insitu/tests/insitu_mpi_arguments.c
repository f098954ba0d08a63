/* Argument checks over MPI (issue 26, C1: one rank's abort killed the job).
 * A handle that is no communicator: darkroom_insitu_set_mpi_comm fails with
 * a message instead of letting MPI's default error handler abort the job,
 * and the session still takes a good handle afterwards. A camera far beyond
 * the data, each rank holding a part: every rank's capture is refused with
 * the same message, none aborts or waits. Run by ctest under mpiexec. */
#include <darkroom/insitu.h>
#include <mpi.h>

#include <stdio.h>
#include <string.h>

#define EXPECT(c)                                                              \
    do {                                                                       \
        if (!(c)) {                                                            \
            fprintf(stderr, "%s:%d: expected %s\n", __FILE__, __LINE__, #c);  \
            return 1;                                                          \
        }                                                                      \
    } while (0)

static int run(void) {
    darkroom_insitu* s = darkroom_insitu_open("mpi_arguments.cdb", DARKROOM_INSITU_OVERWRITE);
    /* A C handle cast to an int, a freed or never made index: not a Fortran handle. */
    const int bad[] = {123456, -7};
    for (int i = 0; i < 2; ++i) {
        EXPECT(darkroom_insitu_set_mpi_comm(s, bad[i]) == DARKROOM_INSITU_FAILED);
        fprintf(stderr, "refused as expected: %s\n", darkroom_insitu_error(s));
        EXPECT(strstr(darkroom_insitu_error(s), "communicator") != NULL);
    }
    EXPECT(darkroom_insitu_set_mpi_comm(s, (int)MPI_Comm_c2f(MPI_COMM_WORLD)) == DARKROOM_INSITU_OK);

    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    float sphere[4] __attribute__((aligned(16))) = {(float)rank, 0.0f, 0.0f, 0.5f};
    const double target[3] = {0, 0, 0}, up[3] = {0, 0, 1}, angle[1] = {0};
    EXPECT(darkroom_insitu_set_image(s, 4, 4, 30.0, 0.0) == DARKROOM_INSITU_OK);
    EXPECT(darkroom_insitu_camera_orbit(s, target, 1e20, up, angle, 1, angle, 1) == DARKROOM_INSITU_OK);
    EXPECT(darkroom_insitu_begin_step(s, 0.0) == DARKROOM_INSITU_OK);
    EXPECT(darkroom_insitu_points(s, "balls", sphere, 16, 1, NULL, 0.0f) == DARKROOM_INSITU_OK);
    EXPECT(darkroom_insitu_capture(s) == DARKROOM_INSITU_BAD_INPUT);
    fprintf(stderr, "refused as expected: %s\n", darkroom_insitu_error(s));
    EXPECT(strstr(darkroom_insitu_error(s), "distance 1e+20 is too far") != NULL);
    EXPECT(darkroom_insitu_close(s) == DARKROOM_INSITU_OK);
    return 0;
}

int main(int argc, char** argv) {
    MPI_Init(&argc, &argv);
    const int failed = run();
    MPI_Finalize();
    return failed;
}
