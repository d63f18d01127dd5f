/* stub: to be written */
typedef int acbb_stub_cli;
int main(void){return 0;}
