// DeadConnectionRescue against the MRPT 2.5.8 behaviour it exists for: a
// CClientTCPSocket write to a connection the peer has reset never returns.
#include <gtest/gtest.h>
#include <mrpt/comms/CClientTCPSocket.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <csignal>
#include <chrono>
#include <thread>

#include "featloc/live/DeadConnectionRescue.h"
#include "featloc/sim/LoopbackTcpServer.h"
#include "support/FreePort.h"

using featloc::DeadConnectionRescue;
using featloc::LoopbackTcpServer;

namespace
{
/** A loopback connection: MRPT's client socket and the server's end. */
struct Connection
{
	unsigned short port = featloc::test::freePort();
	LoopbackTcpServer server{port};
	mrpt::comms::CClientTCPSocket client;
	int accepted = -1;
	Connection()
	{
		client.connect("127.0.0.1", port);
		accepted = server.accept(1000);
	}
};
}  // namespace

TEST(DeadConnectionRescue, FreesAnMrptWriteLoopingOnAResetConnection)
{
	std::signal(SIGPIPE, SIG_IGN);	// as featloc-live does
	Connection c;
	auto& client = c.client;
	const int accepted = c.accepted;
	ASSERT_GE(accepted, 0);
	// The device resets the connection (close with a zero linger: RST).
	const linger reset{1, 0};
	::setsockopt(accepted, SOL_SOCKET, SO_LINGER, &reset, sizeof(reset));
	::close(accepted);
	std::this_thread::sleep_for(std::chrono::milliseconds(50));

	std::atomic<bool> returned{false};
	std::thread writer([&] {
		const char command[] = "QT\n";
		client.writeAsync(command, 3);	// what CHokuyoURG::sendCmd does (Write)
		returned = true;
	});
	std::this_thread::sleep_for(std::chrono::milliseconds(300));
	// MRPT's loop: still inside the write 300 ms later.
	EXPECT_FALSE(returned.load());
	EXPECT_GE(DeadConnectionRescue::rescueAll(), 1u);
	const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(2);
	while (!returned && std::chrono::steady_clock::now() < until)
		std::this_thread::sleep_for(std::chrono::milliseconds(5));
	ASSERT_TRUE(returned.load()) << "the write still loops";
	writer.join();
	// Then the connection reads as closed, as on any dead device.
	char buf[8];
	EXPECT_EQ(client.readAsync(buf, sizeof(buf), 200, 50), 0u);
	EXPECT_FALSE(client.isConnected());
}

TEST(DeadConnectionRescue, LeavesLiveConnectionsAlone)
{
	Connection c;
	auto& client = c.client;
	const int accepted = c.accepted;
	ASSERT_GE(accepted, 0);
	EXPECT_EQ(DeadConnectionRescue::rescueAll(), 0u);
	ASSERT_TRUE(LoopbackTcpServer::sendAll(accepted, "hello", 1000));
	char buf[8] = {};
	EXPECT_EQ(client.readAsync(buf, 5, 1000, 100), 5u);
	EXPECT_EQ(std::string(buf, 5), "hello");
	::close(accepted);
}
