!> The kinds of system a scene (`&scene model`) and a C program (`hillstab_system_new_named`)
!> can name, in one place: each kind's name, what it is in a message and in a template's list
!> of models, and an empty system of it. A new kind is its module (a type extending
!> `hill_system_t`, hillstab_hill_system) plus its row here: its name in `system_names` and
!> its cases in `new_system`, `system_purpose` and `system_choice`; the scene reader, the
!> templates and the C API find it here.
!>
!> Kinds:
!> - `system`: n coupled equations M x'' + (C + G) x' + K(τ) x = 0, the matrices in `&system`
!>   (hillstab_hill_system_matrix);
!> - `equations`: n coupled equations in physical time, or the first-order form y' = A(t) y,
!>   with named parameters and matrices (`&equations`, hillstab_hill_system_equation).
!>
!>```fortran
!> class(hill_system_t), allocatable :: system
!> type(error_t), allocatable :: error
!> call new_system("equations", system, error)
!>```
module hillstab_hill_systems
   use hillstab_core_error, only: error_t, set_error, err_invalid_parameter
   use hillstab_core_text, only: name_position
   use hillstab_hill_system, only: hill_system_t
   use hillstab_hill_system_matrix, only: matrix_system_t
   use hillstab_hill_system_equation, only: equations_system_t
   implicit none
   private
   public :: system_names, new_system, is_system_name, system_purpose, system_choice, system_kinds_text

   !> The kinds' names, as `&scene model` and `hillstab_system_new_named` take them.
   character(len=*), parameter :: system_names(2) = [character(len=9) :: "system", "equations"]

contains

   !> An empty system of the kind `name` (any case, blanks trimmed); err_invalid_parameter
   !> naming the kinds when there is none.
   subroutine new_system(name, system, error)
      character(len=*), intent(in) :: name  !! a kind's name
      class(hill_system_t), allocatable, intent(out) :: system  !! the system, its variables at their defaults
      type(error_t), allocatable, intent(out) :: error  !! unknown kind
      select case (name_position(name, system_names))
      case (1); allocate (matrix_system_t :: system)
      case (2); allocate (equations_system_t :: system)
      case default
         call set_error(error, err_invalid_parameter, "unknown system '"//trim(adjustl(name))//"' ("// &
                        system_kinds_text("", "; ")//")")
      end select
   end subroutine new_system

   !> Whether `name` (any case, blanks trimmed) is a kind of system.
   pure logical function is_system_name(name)
      character(len=*), intent(in) :: name  !! a name
      is_system_name = name_position(name, system_names) > 0
   end function is_system_name

   !> What the kind `name` is, for messages ("" for a name that is none).
   pure function system_purpose(name) result(text)
      character(len=*), intent(in) :: name  !! a kind's name
      character(len=:), allocatable :: text
      select case (name_position(name, system_names))
      case (1); text = "n coupled equations, the matrices in &system"
      case (2); text = "n coupled equations in physical time, &equations"
      case default; text = ""
      end select
   end function system_purpose

   !> The kind `name` in a template's list of models: its equation, its group, its tasks and
   !> its guide page ("" for a name that is none).
   pure function system_choice(name) result(text)
      character(len=*), intent(in) :: name  !! a kind's name
      character(len=:), allocatable :: text
      select case (name_position(name, system_names))
      case (1)
         text = "system: n coupled equations M x'' + (C + G) x' + K(tau) x = 0, the matrices in &system (tasks "// &
                "chart, points, coefficient, boundaries, regions, edges; guide page Coupled systems)"
      case (2)
         text = "equations: n coupled equations M x'' + (C + G) x' + K(t) x = 0 in physical time, or the "// &
                "first-order form y' = A(t) y (state), with named parameters and matrices (&equations; guide page "// &
                "Your problem as you write it)"
      case default; text = ""
      end select
   end function system_choice

   !> Every kind with its purpose for a message: `prefix`'name': purpose, joined by `separator`
   !> ("system: n coupled …; equations: …" with prefix "" and separator "; ").
   pure function system_kinds_text(prefix, separator, quote) result(text)
      character(len=*), intent(in) :: prefix     !! before each kind (e.g. "or ")
      character(len=*), intent(in) :: separator  !! between two kinds
      logical, intent(in), optional :: quote     !! the names in single quotes
      character(len=:), allocatable :: text
      character(len=:), allocatable :: mark
      integer :: k
      mark = ""
      if (present(quote)) then
         if (quote) mark = "'"
      end if
      text = ""
      do k = 1, size(system_names)
         if (k > 1) text = text//separator
         text = text//prefix//mark//trim(system_names(k))//mark//": "//system_purpose(system_names(k))
      end do
   end function system_kinds_text
end module hillstab_hill_systems
