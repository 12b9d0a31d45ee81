! gfortran 12 artefact behind LeakSanitizer's reports from the test harness (issue 19, the
! sanitizer build): an array constructor of function results whose type has an allocatable
! component, as `[new_unittest("a", a), new_unittest("b", b)]` was, copies each result into
! the constructor's temporary and frees neither the results' components nor the copies'.
! Assigning results one by one (`items(1) = new_item("first")`) does not leak; nor does a
! type without allocatable components. testing/src/hillstab_testing.f90 and test/main.f90 do that.
module constructor_leak
   implicit none
   type :: item_t
      character(len=:), allocatable :: name
   end type item_t
contains
   function new_item(name) result(item)
      character(len=*), intent(in) :: name
      type(item_t) :: item
      item%name = name
   end function new_item
end module constructor_leak

program leak
   use constructor_leak, only: item_t, new_item
   implicit none
   type(item_t), allocatable :: items(:)
   items = [new_item("first"), new_item("second")]
   print '(a, 1x, a)', items(1)%name, items(2)%name
   deallocate (items)
end program leak
