// ncc command line (being assembled; see driver/).
int main() { return 2; }
