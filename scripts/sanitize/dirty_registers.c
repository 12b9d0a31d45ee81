/* Calls outer() of absent_optional.f90 with its array absent and large values left in the
   callee-saved registers where gfortran -O0 keeps the strides it never sets when the array
   is absent: they stand for whatever a real caller leaves there (x86-64 only). */
#include <stdio.h>
void __absent_optional_MOD_outer(void *a);
__attribute__((noinline)) static void call_outer(long junk)
{
   __asm__ volatile("mov %0, %%rbx\n\tmov %0, %%r12\n\tmov %0, %%r13\n\tmov %0, %%r14\n\t"
                    "xor %%edi, %%edi\n\tcall __absent_optional_MOD_outer"
                    :
                    : "r"(junk)
                    : "rbx", "r12", "r13", "r14", "rdi", "rax", "rcx", "rdx", "rsi", "r8", "r9", "r10", "r11",
                      "memory");
}
int main(void)
{
   call_outer(0x4000000000000001L);
   puts("outer() returned: the absent array went on as absent (the overflow is in a discarded descriptor)");
   return 0;
}
