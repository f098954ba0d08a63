/* The in situ API from C (C99): a session writes two time steps of a
 * triangle and a few spheres for two cameras; `darkroom info` then checks
 * the database (CMakeLists.txt). Also checks that bad calls are refused
 * with a message and that nothing is copied. Exits non-zero on failure. */
#include <darkroom/insitu.h>

#include <stdio.h>
#include <string.h>

static int failures = 0;

#define EXPECT(cond)                                                     \
    do {                                                                 \
        if (!(cond)) {                                                   \
            fprintf(stderr, "%s:%d: expected %s\n", __FILE__, __LINE__, #cond); \
            ++failures;                                                  \
        }                                                                \
    } while (0)

int main(int argc, char** argv) {
    const char* path = argc > 1 ? argv[1] : "insitu_from_c.cdb";
    darkroom_insitu* s = darkroom_insitu_open(path, DARKROOM_INSITU_OVERWRITE);
    const double target[3] = {0, 0, 0}, up[3] = {0, 1, 0};
    const double phi[2] = {0, 90}, theta[1] = {20};
    EXPECT(darkroom_insitu_set_image(s, 32, 24, 40.0, 0.0) == DARKROOM_INSITU_OK);
    EXPECT(darkroom_insitu_camera_orbit(s, target, 4.0, up, phi, 2, theta, 1) == DARKROOM_INSITU_OK);
    EXPECT(darkroom_insitu_request_field(s, "temperature") == DARKROOM_INSITU_OK);
    EXPECT(darkroom_insitu_request_normals(s, 1) == DARKROOM_INSITU_OK);

    /* A triangle with x, y, z, pad records and spheres with x, y, z, radius. */
    float triangle[12] = {-1, -1, 0, 0, 1, -1, 0, 0, 0, 1, 0, 0};
    const uint32_t corners[3] = {0, 1, 2};
    float temperature[3] = {0, 1, 2};
    float spheres[8] = {0.5f, 0.5f, 0.3f, 0.2f, -0.5f, 0.2f, 0.4f, 0.1f};
    for (int step = 0; step < 2; ++step) {
        EXPECT(darkroom_insitu_begin_step(s, 0.5 * step) == DARKROOM_INSITU_OK);
        EXPECT(darkroom_insitu_triangles(s, "plate", triangle, 16, 3, corners, 1) == DARKROOM_INSITU_OK);
        EXPECT(darkroom_insitu_field(s, "plate", "temperature", temperature, 3, DARKROOM_INSITU_POINT_DATA) ==
               DARKROOM_INSITU_OK);
        EXPECT(darkroom_insitu_points(s, "drops", spheres, 16, 2, NULL, 0.0f) == DARKROOM_INSITU_OK);
        EXPECT(darkroom_insitu_capture(s) == DARKROOM_INSITU_OK);
        if (failures) fprintf(stderr, "last error: %s\n", darkroom_insitu_error(s));
        temperature[2] += 1.0f;
    }
    EXPECT(darkroom_insitu_rows_written(s) == 4);
    EXPECT(darkroom_insitu_copied_bytes(s) == 0);

    /* Refused with a message, and the session goes on. */
    EXPECT(darkroom_insitu_triangles(s, "bad", triangle, 8, 3, corners, 1) == DARKROOM_INSITU_BAD_INPUT);
    EXPECT(strstr(darkroom_insitu_error(s), "8 bytes apart") != NULL);
    EXPECT(darkroom_insitu_field(s, "nothing", "temperature", temperature, 3, 0) == DARKROOM_INSITU_BAD_INPUT);
    EXPECT(strstr(darkroom_insitu_error(s), "no object 'nothing'") != NULL);

    EXPECT(darkroom_insitu_close(s) == DARKROOM_INSITU_OK);
    if (failures) fprintf(stderr, "%d failures\n", failures);
    return failures ? 1 : 0;
}
