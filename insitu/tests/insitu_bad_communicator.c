/* A communicator handle that is no communicator (issue 26: every argument
 * checked): darkroom_insitu_set_mpi_comm fails with a message on every rank
 * instead of letting MPI's default error handler abort the job, and the
 * session still takes a good handle afterwards. Run by ctest under mpiexec. */
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
    darkroom_insitu* s = darkroom_insitu_open("bad_communicator.cdb", DARKROOM_INSITU_OVERWRITE);
    /* A C handle cast to an int, a freed or never made index: not a Fortran handle. */
    const int bad[] = {123456, -7};
    for (int i = 0; i < 2; ++i) {
        EXPECT(darkroom_insitu_set_mpi_comm(s, bad[i]) == DARKROOM_INSITU_FAILED);
        fprintf(stderr, "refused as expected: %s\n", darkroom_insitu_error(s));
        EXPECT(strstr(darkroom_insitu_error(s), "communicator") != NULL);
    }
    EXPECT(darkroom_insitu_set_mpi_comm(s, (int)MPI_Comm_c2f(MPI_COMM_WORLD)) == DARKROOM_INSITU_OK);
    EXPECT(darkroom_insitu_close(s) == DARKROOM_INSITU_OK);
    return 0;
}

int main(int argc, char** argv) {
    MPI_Init(&argc, &argv);
    const int failed = run();
    MPI_Finalize();
    return failed;
}
