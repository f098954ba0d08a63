! The in situ API from Fortran (module darkroom_insitu): a small height field
! of (4, n) x, y, z, radius records and streamline-like lines, three listed
! cameras, two time steps; `darkroom info` then checks the database
! (CMakeLists.txt). Stops with an error on any failure.
program insitu_from_fortran
  use, intrinsic :: iso_c_binding
  use darkroom_insitu
  implicit none
  type(c_ptr) :: s
  integer, parameter :: n = 6
  real(c_float), target :: grid(4, n * n), curve(4, 5), height(n * n)
  integer(c_int32_t), target :: tris(3, 2 * (n - 1) * (n - 1)), segs(4)
  integer :: i, j, k, step

  s = darkroom_insitu_open("insitu_from_fortran.cdb", DARKROOM_INSITU_OVERWRITE)
  call check(darkroom_insitu_set_image(s, 24, 24, 35.0_c_double, 0.0_c_double))
  call check(darkroom_insitu_add_camera(s, [0d0, 0d0, 4d0], [0d0, 0d0, 0d0], [0d0, 1d0, 0d0]))
  call check(darkroom_insitu_add_camera(s, [4d0, 0d0, 0d0], [0d0, 0d0, 0d0], [0d0, 1d0, 0d0]))
  call check(darkroom_insitu_add_camera(s, [0d0, 4d0, 0.1d0], [0d0, 0d0, 0d0], [0d0, 0d0, 1d0]))
  call check(darkroom_insitu_request_field(s, "height"))
  call check(darkroom_insitu_request_ids(s, .true., .true.))

  k = 0
  do j = 0, n - 2
    do i = 0, n - 2
      tris(:, k + 1) = [j * n + i, j * n + i + 1, (j + 1) * n + i + 1]
      tris(:, k + 2) = [j * n + i, (j + 1) * n + i + 1, (j + 1) * n + i]
      k = k + 2
    end do
  end do
  segs = [0, 1, 2, 3]

  do step = 0, 1
    do j = 0, n - 1
      do i = 0, n - 1
        k = j * n + i + 1
        grid(1, k) = -1.0 + 2.0 * i / (n - 1)
        grid(2, k) = -1.0 + 2.0 * j / (n - 1)
        grid(3, k) = 0.2 * sin(3.0 * grid(1, k) + step)
        grid(4, k) = 0.0
        height(k) = grid(3, k)
      end do
    end do
    do i = 1, 5
      curve(:, i) = [-1.0 + 0.5 * (i - 1), 0.3 * step, 0.5, 0.05]
    end do
    call check(darkroom_insitu_begin_step(s, 0.25d0 * step))
    call check(darkroom_insitu_triangles(s, "surface", grid, tris))
    call check(darkroom_insitu_field(s, "surface", "height", height, DARKROOM_INSITU_POINT_DATA))
    call check(darkroom_insitu_lines(s, "curve", curve, segs))
    call check(darkroom_insitu_capture(s))
  end do
  if (darkroom_insitu_rows_written(s) /= 6) error stop "expected 6 rows"
  if (darkroom_insitu_copied_bytes(s) /= 0) error stop "expected the arrays to be shared, not copied"
  ! A strided section would be copied into a temporary: refused with a message.
  if (darkroom_insitu_field(s, "surface", "height", height(1:n*n:2), 0) /= DARKROOM_INSITU_BAD_INPUT) &
    error stop "expected a non-contiguous field to be refused"
  if (index(darkroom_insitu_error(s), "not contiguous") == 0) error stop "expected the message to say why"
  call check(darkroom_insitu_close(s))

contains

  subroutine check(status)
    integer, intent(in) :: status
    if (status /= DARKROOM_INSITU_OK) then
      print *, "darkroom_insitu: ", darkroom_insitu_error(s)
      error stop 1
    end if
  end subroutine

end program
