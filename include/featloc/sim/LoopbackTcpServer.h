#pragma once
#include <string>

namespace featloc
{
/** A listening TCP socket on 127.0.0.1 and the few operations the device
 * emulators need on their client connections, over POSIX sockets.
 *
 * Why not MRPT's CServerTCPSocket / CClientTCPSocket: in MRPT 2.5.8
 * CClientTCPSocket::writeAsync() never returns once the peer has closed
 * (epoll keeps reporting the socket writable, send() keeps failing), so an
 * emulator whose driver hangs up would spin forever; here a failed send
 * ends the connection (MSG_NOSIGNAL: no SIGPIPE either). */
class LoopbackTcpServer
{
   public:
	/** Listens on 127.0.0.1:port (SO_REUSEADDR); throws std::runtime_error
	 * naming the port and the system's reason when it cannot. */
	explicit LoopbackTcpServer(unsigned short port);
	~LoopbackTcpServer();
	LoopbackTcpServer(const LoopbackTcpServer&) = delete;
	LoopbackTcpServer& operator=(const LoopbackTcpServer&) = delete;

	/** A new connection's descriptor (TCP_NODELAY set), or -1 when none
	 * came within timeoutMs. */
	int accept(int timeoutMs) const;

	/** Sends all of `bytes` within timeoutMs; false (the connection is
	 * then useless: close it) when the peer is gone or does not read. */
	static bool sendAll(int fd, const std::string& bytes, int timeoutMs);
	/** What has arrived, without waiting: the byte count, 0 when nothing,
	 * -1 when the peer closed the connection. */
	static long receive(int fd, char* buffer, size_t size);
	static void close(int fd);

   private:
	int m_fd = -1;
};
}  // namespace featloc
