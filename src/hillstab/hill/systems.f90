!> The kinds of system a scene (`&scene model`) and a C program (`hillstab_system_new_named`)
!> can name, in one place: each kind's name, what it is in a message and in a template's list
!> of models, and an empty system of it. A new kind is its module (a type extending
!> `hill_system_t`, hillstab_hill_system) plus its row here: a `system_kind_t` in
!> `system_kinds` and its case in `new_system`; the scene reader, the templates and the C
!> API find it here.
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
   public :: system_kind_t, system_kinds, system_names, new_system, is_system_name, system_kinds_text

   !> One kind of system: its name, what it is in a message, and its line in a template's list
   !> of models (its equation, its group, its tasks and its guide page).
   type :: system_kind_t
      character(len=9) :: name      !! as `&scene model` and `hillstab_system_new_named` take it
      character(len=60) :: purpose  !! for messages
      character(len=240) :: choice  !! for a template's list of models
   end type system_kind_t

   !> The kinds, one row each (the order of `new_system`'s cases).
   type(system_kind_t), parameter :: system_kinds(2) = [ &
      system_kind_t("system", "n coupled equations, the matrices in &system", &
                    "system: n coupled equations M x'' + (C + G) x' + K(tau) x = 0, the matrices in &system (tasks "// &
                    "chart, points, coefficient, boundaries, regions, edges; guide page Coupled systems)"), &
      system_kind_t("equations", "n coupled equations in physical time, &equations", &
                    "equations: n coupled equations M x'' + (C + G) x' + K(t) x = 0 in physical time, or the "// &
                    "first-order form y' = A(t) y (state), with named parameters and matrices (&equations; guide "// &
                    "page Your problem as you write it)")]
   !> The kinds' names, as `&scene model` and `hillstab_system_new_named` take them.
   character(len=*), parameter :: system_names(size(system_kinds)) = system_kinds%name

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
         text = text//prefix//mark//trim(system_names(k))//mark//": "//trim(system_kinds(k)%purpose)
      end do
   end function system_kinds_text
end module hillstab_hill_systems
