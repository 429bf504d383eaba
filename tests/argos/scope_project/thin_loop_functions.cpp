// Registers nothing: its loop functions are those of libtwin_loop_functions, which it needs.
int ThinLoopFunctions() { return 0; }
