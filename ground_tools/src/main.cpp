// tolip: command-line entry point (subcommands live in ground_tools/src/commands/).
int main() { return 0; }
