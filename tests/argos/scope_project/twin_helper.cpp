// A library of the experiment that is no loop functions: it defines what another one uses.
extern "C" const char* TwinHelperWord() { return "helped"; }
