package minigolf.online.server;

import java.io.ByteArrayOutputStream;
import java.io.DataInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Predicate;

/**
 * A TCP relay between WebSocket clients and a server on the loopback address that loses chosen
 * client messages on the way: the server never sees them and nothing answers them, as with a
 * message lost in the network. It reads the client's frames (RFC 6455: unextended, masked; the
 * JDK's client negotiates no compression) and passes everything else through byte for byte.
 */
final class LossyProxy implements AutoCloseable {
    private final ServerSocket listener;
    private final int target;
    private final Predicate<String> lose;
    private final AtomicInteger lost = new AtomicInteger();
    private final List<Socket> sockets = new CopyOnWriteArrayList<>();

    /** Relays to {@code targetPort}; a client text message for which {@code lose} says true is dropped. */
    LossyProxy(int targetPort, Predicate<String> lose) throws IOException {
        this.target = targetPort;
        this.lose = lose;
        listener = new ServerSocket(0, 50, InetAddress.getLoopbackAddress());
        daemon(this::accept, "lossy-proxy-accept");
    }

    int port() {
        return listener.getLocalPort();
    }

    /** How many client messages were lost so far. */
    int lost() {
        return lost.get();
    }

    private void accept() {
        try {
            while (true) {
                Socket client = listener.accept();
                Socket server = new Socket(InetAddress.getLoopbackAddress(), target);
                sockets.add(client);
                sockets.add(server);
                daemon(() -> relayFrames(client, server), "lossy-proxy-up");
                daemon(() -> copy(server, client), "lossy-proxy-down");
            }
        } catch (IOException closed) {
            // the proxy was closed
        }
    }

    /** Client to server: the HTTP upgrade as it is, then frame by frame, leaving out the lost messages. */
    private void relayFrames(Socket from, Socket to) {
        try (DataInputStream in = new DataInputStream(from.getInputStream()); OutputStream out = to.getOutputStream()) {
            ByteArrayOutputStream head = new ByteArrayOutputStream();
            while (!head.toString(StandardCharsets.ISO_8859_1).endsWith("\r\n\r\n")) {
                int b = in.read();
                if (b < 0) return;
                head.write(b);
            }
            out.write(head.toByteArray());
            out.flush();
            while (true) {
                ByteArrayOutputStream frame = new ByteArrayOutputStream();
                int b0 = in.readUnsignedByte(), b1 = in.readUnsignedByte();
                frame.write(b0);
                frame.write(b1);
                long length = b1 & 0x7f;
                if (length >= 126) {
                    byte[] ext = new byte[length == 126 ? 2 : 8];
                    in.readFully(ext);
                    frame.write(ext);
                    length = 0;
                    for (byte e : ext) length = length << 8 | (e & 0xff);
                }
                byte[] mask = new byte[(b1 & 0x80) != 0 ? 4 : 0];
                in.readFully(mask);
                frame.write(mask);
                byte[] payload = new byte[Math.toIntExact(length)];
                in.readFully(payload);
                frame.write(payload);
                boolean wholeText = (b0 & 0x80) != 0 && (b0 & 0x0f) == 1;
                if (wholeText && lose.test(unmasked(payload, mask))) {
                    lost.incrementAndGet();
                    continue;
                }
                out.write(frame.toByteArray());
                out.flush();
            }
        } catch (IOException closed) {
            // either side closed
        } finally {
            closeQuietly(to);
        }
    }

    private static String unmasked(byte[] payload, byte[] mask) {
        byte[] text = payload.clone();
        for (int i = 0; mask.length > 0 && i < text.length; i++) text[i] ^= mask[i % 4];
        return new String(text, StandardCharsets.UTF_8);
    }

    private static void copy(Socket from, Socket to) {
        try (InputStream in = from.getInputStream(); OutputStream out = to.getOutputStream()) {
            byte[] buffer = new byte[8192];
            for (int n; (n = in.read(buffer)) >= 0; ) {
                out.write(buffer, 0, n);
                out.flush();
            }
        } catch (IOException closed) {
            // either side closed
        } finally {
            closeQuietly(to);
        }
    }

    private static void daemon(Runnable r, String name) {
        Thread t = new Thread(r, name);
        t.setDaemon(true);
        t.start();
    }

    private static void closeQuietly(Socket s) {
        try {
            s.close();
        } catch (IOException ignored) {
            // already closed
        }
    }

    @Override
    public void close() throws IOException {
        listener.close();
        for (Socket s : sockets) closeQuietly(s);
    }
}
