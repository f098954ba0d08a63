! Fortran binding of darkroom/insitu.h (ISO_C_BINDING): the same calls, with
! Fortran strings and arrays. Arrays are shared with the ray tracer, not
! copied: they must be contiguous, have the TARGET attribute, and stay
! unchanged until darkroom_insitu_capture returns. A non-contiguous array
! section is refused (DARKROOM_INSITU_BAD_INPUT) rather than copied behind
! your back into a temporary that would be gone by the capture.
!
! Vertices are real(c_float) arrays of shape (3, n) (x, y, z) or (4, n)
! (x, y, z, radius); triangles integer(c_int32_t) (3, m) and segments (m),
! holding 0-based vertex indices as in C. The communicator is the Fortran
! integer handle (MPI_COMM_WORLD from `use mpi`).
module darkroom_insitu
  use, intrinsic :: iso_c_binding
  implicit none
  private

  integer, parameter, public :: DARKROOM_INSITU_OK = 0, DARKROOM_INSITU_FAILED = 1, DARKROOM_INSITU_BAD_INPUT = 2
  integer, parameter, public :: DARKROOM_INSITU_CREATE = 0, DARKROOM_INSITU_OVERWRITE = 1, DARKROOM_INSITU_RESUME = 2
  integer, parameter, public :: DARKROOM_INSITU_POINT_DATA = 0, DARKROOM_INSITU_CELL_DATA = 1

  public :: darkroom_insitu_open, darkroom_insitu_set_mpi_comm, darkroom_insitu_set_threads, &
            darkroom_insitu_set_image, darkroom_insitu_camera_orbit, darkroom_insitu_add_camera, &
            darkroom_insitu_request_field, darkroom_insitu_request_normals, darkroom_insitu_request_ids, &
            darkroom_insitu_begin_step, darkroom_insitu_triangles, darkroom_insitu_lines, darkroom_insitu_points, &
            darkroom_insitu_field, darkroom_insitu_capture, darkroom_insitu_close, darkroom_insitu_error, &
            darkroom_insitu_copied_bytes, darkroom_insitu_rows_written

  interface
    function c_open(database, mode) bind(C, name="darkroom_insitu_open")
      import :: c_ptr, c_char, c_int
      character(kind=c_char), dimension(*), intent(in) :: database
      integer(c_int), value :: mode
      type(c_ptr) :: c_open
    end function
    integer(c_int) function c_set_mpi_comm(s, comm) bind(C, name="darkroom_insitu_set_mpi_comm")
      import :: c_ptr, c_int
      type(c_ptr), value :: s
      integer(c_int), value :: comm
    end function
    integer(c_int) function c_set_threads(s, threads) bind(C, name="darkroom_insitu_set_threads")
      import :: c_ptr, c_int
      type(c_ptr), value :: s
      integer(c_int), value :: threads
    end function
    integer(c_int) function c_set_image(s, width, height, fov, view_height) bind(C, name="darkroom_insitu_set_image")
      import :: c_ptr, c_int, c_double
      type(c_ptr), value :: s
      integer(c_int), value :: width, height
      real(c_double), value :: fov, view_height
    end function
    integer(c_int) function c_camera_orbit(s, target, distance, up, phi, nphi, theta, ntheta) &
        bind(C, name="darkroom_insitu_camera_orbit")
      import :: c_ptr, c_int, c_double
      type(c_ptr), value :: s
      real(c_double), dimension(3), intent(in) :: target, up
      real(c_double), value :: distance
      real(c_double), dimension(*), intent(in) :: phi, theta
      integer(c_int), value :: nphi, ntheta
    end function
    integer(c_int) function c_add_camera(s, position, target, up) bind(C, name="darkroom_insitu_add_camera")
      import :: c_ptr, c_int, c_double
      type(c_ptr), value :: s
      real(c_double), dimension(3), intent(in) :: position, target, up
    end function
    integer(c_int) function c_request_field(s, name) bind(C, name="darkroom_insitu_request_field")
      import :: c_ptr, c_int, c_char
      type(c_ptr), value :: s
      character(kind=c_char), dimension(*), intent(in) :: name
    end function
    integer(c_int) function c_request_normals(s, on) bind(C, name="darkroom_insitu_request_normals")
      import :: c_ptr, c_int
      type(c_ptr), value :: s
      integer(c_int), value :: on
    end function
    integer(c_int) function c_request_ids(s, objects, primitives) bind(C, name="darkroom_insitu_request_ids")
      import :: c_ptr, c_int
      type(c_ptr), value :: s
      integer(c_int), value :: objects, primitives
    end function
    integer(c_int) function c_begin_step(s, time) bind(C, name="darkroom_insitu_begin_step")
      import :: c_ptr, c_int, c_double
      type(c_ptr), value :: s
      real(c_double), value :: time
    end function
    integer(c_int) function c_triangles(s, name, vertices, stride, nv, triangles, nt) &
        bind(C, name="darkroom_insitu_triangles")
      import :: c_ptr, c_int, c_char, c_size_t, c_int64_t
      type(c_ptr), value :: s, vertices, triangles
      character(kind=c_char), dimension(*), intent(in) :: name
      integer(c_size_t), value :: stride
      integer(c_int64_t), value :: nv, nt
    end function
    integer(c_int) function c_lines(s, name, vertices, stride, nv, segments, ns, radii, radius) &
        bind(C, name="darkroom_insitu_lines")
      import :: c_ptr, c_int, c_char, c_size_t, c_int64_t, c_float
      type(c_ptr), value :: s, vertices, segments, radii
      character(kind=c_char), dimension(*), intent(in) :: name
      integer(c_size_t), value :: stride
      integer(c_int64_t), value :: nv, ns
      real(c_float), value :: radius
    end function
    integer(c_int) function c_points(s, name, vertices, stride, nv, radii, radius) bind(C, name="darkroom_insitu_points")
      import :: c_ptr, c_int, c_char, c_size_t, c_int64_t, c_float
      type(c_ptr), value :: s, vertices, radii
      character(kind=c_char), dimension(*), intent(in) :: name
      integer(c_size_t), value :: stride
      integer(c_int64_t), value :: nv
      real(c_float), value :: radius
    end function
    integer(c_int) function c_field(s, object, name, values, count, association) bind(C, name="darkroom_insitu_field")
      import :: c_ptr, c_int, c_char, c_int64_t
      type(c_ptr), value :: s, values
      character(kind=c_char), dimension(*), intent(in) :: object, name
      integer(c_int64_t), value :: count
      integer(c_int), value :: association
    end function
    integer(c_int) function c_capture(s) bind(C, name="darkroom_insitu_capture")
      import :: c_ptr, c_int
      type(c_ptr), value :: s
    end function
    integer(c_int) function c_close(s) bind(C, name="darkroom_insitu_close")
      import :: c_ptr, c_int
      type(c_ptr), value :: s
    end function
    type(c_ptr) function c_error(s) bind(C, name="darkroom_insitu_error")
      import :: c_ptr
      type(c_ptr), value :: s
    end function
    integer(c_int64_t) function c_copied_bytes(s) bind(C, name="darkroom_insitu_copied_bytes")
      import :: c_ptr, c_int64_t
      type(c_ptr), value :: s
    end function
    integer(c_int64_t) function c_rows_written(s) bind(C, name="darkroom_insitu_rows_written")
      import :: c_ptr, c_int64_t
      type(c_ptr), value :: s
    end function
    integer(c_int) function c_report_error(s, message) bind(C, name="darkroom_insitu_report_error")
      import :: c_ptr, c_int, c_char
      type(c_ptr), value :: s
      character(kind=c_char), dimension(*), intent(in) :: message
    end function
    integer(c_size_t) function c_strlen(s) bind(C, name="strlen")
      import :: c_ptr, c_size_t
      type(c_ptr), value :: s
    end function
  end interface

contains

  function cstr(text) result(out)
    character(len=*), intent(in) :: text
    character(kind=c_char, len=len_trim(text) + 1) :: out
    out = trim(text) // c_null_char
  end function

  integer function refused(s, what)
    type(c_ptr), intent(in) :: s
    character(len=*), intent(in) :: what
    refused = c_report_error(s, cstr(what // " is not contiguous; pass a whole array or a contiguous copy"))
  end function

  type(c_ptr) function darkroom_insitu_open(database, mode)
    character(len=*), intent(in) :: database
    integer, intent(in) :: mode
    darkroom_insitu_open = c_open(cstr(database), int(mode, c_int))
  end function

  integer function darkroom_insitu_set_mpi_comm(s, comm)
    type(c_ptr), intent(in) :: s
    integer, intent(in) :: comm
    darkroom_insitu_set_mpi_comm = c_set_mpi_comm(s, int(comm, c_int))
  end function

  integer function darkroom_insitu_set_threads(s, threads)
    type(c_ptr), intent(in) :: s
    integer, intent(in) :: threads
    darkroom_insitu_set_threads = c_set_threads(s, int(threads, c_int))
  end function

  integer function darkroom_insitu_set_image(s, width, height, fov, view_height)
    type(c_ptr), intent(in) :: s
    integer, intent(in) :: width, height
    real(c_double), intent(in) :: fov, view_height
    darkroom_insitu_set_image = c_set_image(s, int(width, c_int), int(height, c_int), fov, view_height)
  end function

  integer function darkroom_insitu_camera_orbit(s, target, distance, up, phi, theta)
    type(c_ptr), intent(in) :: s
    real(c_double), intent(in) :: target(3), up(3), distance, phi(:), theta(:)
    real(c_double) :: p(size(phi)), t(size(theta))
    p = phi
    t = theta
    darkroom_insitu_camera_orbit = c_camera_orbit(s, target, distance, up, p, int(size(p), c_int), t, &
                                                  int(size(t), c_int))
  end function

  integer function darkroom_insitu_add_camera(s, position, target, up)
    type(c_ptr), intent(in) :: s
    real(c_double), intent(in) :: position(3), target(3), up(3)
    darkroom_insitu_add_camera = c_add_camera(s, position, target, up)
  end function

  integer function darkroom_insitu_request_field(s, name)
    type(c_ptr), intent(in) :: s
    character(len=*), intent(in) :: name
    darkroom_insitu_request_field = c_request_field(s, cstr(name))
  end function

  integer function darkroom_insitu_request_normals(s, on)
    type(c_ptr), intent(in) :: s
    logical, intent(in) :: on
    darkroom_insitu_request_normals = c_request_normals(s, merge(1_c_int, 0_c_int, on))
  end function

  integer function darkroom_insitu_request_ids(s, objects, primitives)
    type(c_ptr), intent(in) :: s
    logical, intent(in) :: objects, primitives
    darkroom_insitu_request_ids = c_request_ids(s, merge(1_c_int, 0_c_int, objects), merge(1_c_int, 0_c_int, primitives))
  end function

  integer function darkroom_insitu_begin_step(s, time)
    type(c_ptr), intent(in) :: s
    real(c_double), intent(in) :: time
    darkroom_insitu_begin_step = c_begin_step(s, time)
  end function

  integer function darkroom_insitu_triangles(s, name, vertices, triangles)
    type(c_ptr), intent(in) :: s
    character(len=*), intent(in) :: name
    real(c_float), intent(in), target :: vertices(:, :)
    integer(c_int32_t), intent(in), target :: triangles(:, :)
    if (.not. is_contiguous(vertices)) then
      darkroom_insitu_triangles = refused(s, "triangles: vertices")
    else if (.not. is_contiguous(triangles) .or. size(triangles, 1) /= 3) then
      darkroom_insitu_triangles = refused(s, "triangles: the (3, n) index array")
    else
      darkroom_insitu_triangles = c_triangles(s, cstr(name), c_loc(vertices), int(4 * size(vertices, 1), c_size_t), &
                                              int(size(vertices, 2), c_int64_t), c_loc(triangles), &
                                              int(size(triangles, 2), c_int64_t))
    end if
  end function

  ! Radii: from the 4th row of a (4, n) vertex array, or `radius` for (3, n).
  integer function darkroom_insitu_lines(s, name, vertices, segments, radius)
    type(c_ptr), intent(in) :: s
    character(len=*), intent(in) :: name
    real(c_float), intent(in), target :: vertices(:, :)
    integer(c_int32_t), intent(in), target :: segments(:)
    real(c_float), intent(in), optional :: radius
    real(c_float) :: r
    r = 0
    if (present(radius)) r = radius
    if (.not. is_contiguous(vertices) .or. .not. is_contiguous(segments)) then
      darkroom_insitu_lines = refused(s, "lines: vertices or segments")
    else
      darkroom_insitu_lines = c_lines(s, cstr(name), c_loc(vertices), int(4 * size(vertices, 1), c_size_t), &
                                      int(size(vertices, 2), c_int64_t), c_loc(segments), &
                                      int(size(segments), c_int64_t), c_null_ptr, r)
    end if
  end function

  integer function darkroom_insitu_points(s, name, vertices, radius)
    type(c_ptr), intent(in) :: s
    character(len=*), intent(in) :: name
    real(c_float), intent(in), target :: vertices(:, :)
    real(c_float), intent(in), optional :: radius
    real(c_float) :: r
    r = 0
    if (present(radius)) r = radius
    if (.not. is_contiguous(vertices)) then
      darkroom_insitu_points = refused(s, "points: vertices")
    else
      darkroom_insitu_points = c_points(s, cstr(name), c_loc(vertices), int(4 * size(vertices, 1), c_size_t), &
                                        int(size(vertices, 2), c_int64_t), c_null_ptr, r)
    end if
  end function

  integer function darkroom_insitu_field(s, object, name, values, association)
    type(c_ptr), intent(in) :: s
    character(len=*), intent(in) :: object, name
    real(c_float), intent(in), target :: values(:)
    integer, intent(in) :: association
    if (.not. is_contiguous(values)) then
      darkroom_insitu_field = refused(s, "field " // trim(name))
    else
      darkroom_insitu_field = c_field(s, cstr(object), cstr(name), c_loc(values), int(size(values), c_int64_t), &
                                      int(association, c_int))
    end if
  end function

  integer function darkroom_insitu_capture(s)
    type(c_ptr), intent(in) :: s
    darkroom_insitu_capture = c_capture(s)
  end function

  integer function darkroom_insitu_close(s)
    type(c_ptr), intent(inout) :: s
    darkroom_insitu_close = c_close(s)
    s = c_null_ptr
  end function

  function darkroom_insitu_error(s) result(message)
    type(c_ptr), intent(in) :: s
    character(len=:), allocatable :: message
    type(c_ptr) :: p
    character(kind=c_char), pointer :: chars(:)
    integer :: i, n
    p = c_error(s)
    n = int(c_strlen(p))
    call c_f_pointer(p, chars, [n])
    allocate(character(len=n) :: message)
    do i = 1, n
      message(i:i) = chars(i)
    end do
  end function

  integer(c_int64_t) function darkroom_insitu_copied_bytes(s)
    type(c_ptr), intent(in) :: s
    darkroom_insitu_copied_bytes = c_copied_bytes(s)
  end function

  integer(c_int64_t) function darkroom_insitu_rows_written(s)
    type(c_ptr), intent(in) :: s
    darkroom_insitu_rows_written = c_rows_written(s)
  end function

end module darkroom_insitu
