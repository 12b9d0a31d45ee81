!> The exact one-period monodromy Φ of a system of Hill equations (hillstab_hill_system), as
!> its users take it: the 2n × 2n fundamental matrix of y' = A(τ) y over one period, to a
!> tolerance, with an error estimate (`system_monodromy`), and the period's product in
!> well-conditioned factors (`system_factors`), by the system's methods — the rows of the one
!> method table of hillstab_integrate_monodromy that say `systems`, under its codes
!> (`system_auto` … `system_gsl` are those codes, not a numbering of their own) — and the
!> methods' names. The integrators are hillstab_integrate_system_magnus (Magnus of orders 4
!> and 6 on a ladder of meshes, Richardson-controlled; DOP853 on the fundamental matrix) and
!> hillstab_integrate_system_gsl (GSL's rk8pd); the choice among them is
!> hillstab_integrate_monodromy's, beside the scalar methods', so that a new method is its
!> module and its row.
!>
!> In a chart the values of K at the Gauss nodes depend on α and the mesh only (K = p + β b):
!> a `system_nodes_t` keeps them for the meshes used at one α, so that the points of a row
!> share them. No module state: threads each use their own `system_nodes_t`.
!>
!>```fortran
!> type(system_form_t) :: form
!> type(system_monodromy_t) :: result
!> type(system_nodes_t) :: nodes
!> call prepare_system(system, 0.0_wp, form, error)
!> call system_monodromy(system, form, alpha, beta, system_method_t(), nodes, result, error)
!>```
module hillstab_integrate_system
   use hillstab_integrate_monodromy, only: method_table, method_auto, method_magnus4, method_magnus6, method_rk, &
      method_gsl, method_name, method_from_name, method_takes_systems, system_method_t, system_monodromy, system_factors
   use hillstab_integrate_system_magnus, only: system_monodromy_t, system_nodes_t, magnus_ladder, system_exponential
   implicit none
   private
   public :: system_method_t, system_monodromy_t, system_nodes_t, system_monodromy
   public :: system_auto, system_magnus4, system_magnus6, system_rk, system_gsl, system_method_name, system_method_from_name
   public :: system_method_names_text, magnus_ladder, system_exponential, system_factors

   !> Method auto (the table's `method_auto`): Magnus of order 6 with the nodes shared along a chart row.
   integer, parameter :: system_auto = method_auto
   !> The fourth-order Magnus integrator (two Gauss nodes), Richardson-controlled (`method_magnus4`).
   integer, parameter :: system_magnus4 = method_magnus4
   !> The sixth-order Magnus integrator (three Gauss nodes), Richardson-controlled (`method_magnus6`).
   integer, parameter :: system_magnus6 = method_magnus6
   !> Dormand–Prince 8(5,3) on the fundamental matrix, two tolerances (`method_rk`).
   integer, parameter :: system_rk = method_rk
   !> GSL's rk8pd on the fundamental matrix over the whole period, two epsilons
   !> (hillstab_integrate_system_gsl): the reference of another library (`method_gsl`).
   integer, parameter :: system_gsl = method_gsl

contains

   !> The name of a system method: the method table's name, "unknown" for a code that is
   !> not a system's method.
   pure function system_method_name(kind) result(name)
      integer, intent(in) :: kind  !! system_* (a method_* code that `method_takes_systems`)
      character(len=:), allocatable :: name
      if (method_takes_systems(kind)) then
         name = method_name(kind)
      else
         name = "unknown"
      end if
   end function system_method_name

   !> The method of a name, as the method table reads it (any case, blanks trimmed); −1 for
   !> a name that is not a system's method.
   pure integer function system_method_from_name(name) result(kind)
      character(len=*), intent(in) :: name  !! a method name
      kind = method_from_name(name)
      if (.not. method_takes_systems(kind)) kind = -1
   end function system_method_from_name

   !> The methods systems take, for messages: "auto, magnus4, magnus6, rk, gsl" (the table's
   !> rows that say `systems`, in the order of their codes).
   pure function system_method_names_text() result(text)
      character(len=:), allocatable :: text
      integer :: k
      text = ""
      do k = lbound(method_table, 1), ubound(method_table, 1)
         if (.not. method_takes_systems(k)) cycle
         if (len(text) > 0) text = text//", "
         text = text//method_name(k)
      end do
   end function system_method_names_text
end module hillstab_integrate_system
