#pragma once

namespace featloc::test
{
/** A TCP port nobody listens on now on 127.0.0.1 (the kernel's choice),
 * so that tests running in parallel do not collide. */
unsigned short freePort();
}  // namespace featloc::test
