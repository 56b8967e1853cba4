// The ghost pass of shader_5: shader_4's ghost.frag with its factor read from Ghost_Factor, as
// shader_5 also has the glare's Glow_Factor. A variable binds to the uniform of its own name and a
// pass constant only holds a fixed value, so the uniform is renamed here.
#define Glow_Factor Ghost_Factor
#include "ghost.frag"
