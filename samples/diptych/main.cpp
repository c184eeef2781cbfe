#include <cstdio>
int main() { std::puts("diptych: under construction"); return 0; }
