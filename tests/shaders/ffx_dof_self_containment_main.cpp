// The self-containment check is that every generated translation unit (one header each) compiled;
// linking them together also proves the headers define nothing twice.
int main() { return 0; }
