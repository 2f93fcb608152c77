// The rotbeam program: see cases/runner/cli.cpp (being written).
#include <iostream>
int main() {
    std::cerr << "rotbeam: commands are being assembled\n";
    return 2;
}
