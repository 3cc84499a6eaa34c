#pragma once
#include <cstddef>

namespace featloc
{
/** Frees driver threads of this process that loop on send() to a TCP
 * connection the device has reset.
 *
 * Why: MRPT 2.5.8's CClientTCPSocket::writeAsync() never returns once the
 * peer has reset the connection (select() reports the socket writable,
 * send() fails with EPIPE, again, forever), and CHokuyoURG writes its
 * commands with it; such a thread would spin a core until the process
 * ends. A spinning thread never sleeps in a system call, so which socket
 * it writes to cannot be read from /proc.
 *
 * How: every TCP socket of this process that has carried data and is now
 * closed by its peer (state CLOSE: it can neither send nor receive again)
 * is replaced, with dup2() (atomic: the descriptor number is never free
 * for another file), by one end of a fresh socket pair whose writes
 * succeed and whose reads see end-of-file. The stuck write returns, the
 * next read finds the connection closed, and the driver gives up as on
 * any dead device; a driver that had not yet noticed its dead connection
 * notices it the same way. The pairs' other ends and the dead sockets
 * (kept under other numbers, so that an epoll set a stuck write waits on
 * still reports them ready) stay open until the process ends. */
class DeadConnectionRescue
{
   public:
	/** Replaces every such socket now; returns how many. */
	static size_t rescueAll();
};
}  // namespace featloc
