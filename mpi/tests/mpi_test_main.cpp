// GoogleTest under mpirun: every rank runs every test (each test is
// collective); ranks other than 0 print only failures. The exit code is
// non-zero on a rank whose tests failed, which mpirun passes on.
#include <darkroom/mpi/communicator.h>

#include <gtest/gtest.h>

int main(int argc, char** argv) {
    int provided = 0;
    MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
    MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    // Before InitGoogleTest, which picks the printer.
    if (rank != 0) GTEST_FLAG_SET(brief, true);
    ::testing::InitGoogleTest(&argc, argv);
    const int failed = RUN_ALL_TESTS();
    int anyFailed = 0;
    MPI_Allreduce(&failed, &anyFailed, 1, MPI_INT, MPI_LOR, MPI_COMM_WORLD);
    MPI_Finalize();
    return anyFailed ? 1 : 0;
}
