# The fuzz harnesses, one per reader (harnesses/<name>.cpp -> fuzz_<name>),
# shared by tests/fuzz/CMakeLists.txt and cmake/DarkroomFuzz.cmake.
set(DARKROOM_FUZZ_HARNESSES csv pipeline scene ply obj off stl vtk vtkxml npy npz vti exr image colormap legend annotation insitu pointlist staged h5)
# Harnesses whose seeds are written by fuzz_seeds (binary formats) rather
# than committed under corpus/ (stl, ply and vtk have both: ASCII committed,
# binary written).
set(DARKROOM_FUZZ_GENERATED_SEEDS npy npz vti exr image stl h5 ply vtk)
