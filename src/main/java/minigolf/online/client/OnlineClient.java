package minigolf.online.client;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.WebSocket;
import java.time.Duration;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionStage;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import minigolf.online.ClientMessage;
import minigolf.online.ClientMessages;
import minigolf.online.Json;
import minigolf.online.Protocol;
import minigolf.online.ProtocolException;

/**
 * One WebSocket connection to a game server, with the JDK's own client (java.net.http): messages
 * go out in order, each message that comes in is parsed and handed to the listener on the
 * connection's thread. Used by the game, the headless {@code join} client and the benchmark.
 */
public final class OnlineClient implements AutoCloseable {
    /** What the connection reports. */
    public interface Listener {
        void onMessage(ObjectNode message);

        /** The connection ended: closed by the server, or lost ({@code reason} says which). */
        void onClosed(String reason);
    }

    private static final HttpClient SHARED = HttpClient.newBuilder().connectTimeout(Duration.ofSeconds(10)).build();

    private final WebSocket socket;
    private final Object sendLock = new Object();
    private CompletableFuture<?> sending = CompletableFuture.completedFuture(null);
    private volatile boolean closed;

    private OnlineClient(WebSocket socket) {
        this.socket = socket;
    }

    /** The address {@code host:port} as a WebSocket URI; a bad one is an {@link IllegalArgumentException} saying why. */
    public static URI uri(String hostPort) {
        String hp = hostPort.trim();
        if (hp.startsWith("ws://") || hp.startsWith("wss://")) {
            return URI.create(hp.endsWith(Protocol.PATH) ? hp : hp.replaceAll("/+$", "") + Protocol.PATH);
        }
        int colon = hp.lastIndexOf(':');
        if (colon <= 0 || colon == hp.length() - 1) throw new IllegalArgumentException("expected HOST:PORT, got " + hostPort);
        try {
            int port = Integer.parseInt(hp.substring(colon + 1));
            if (port < 1 || port > 65535) throw new IllegalArgumentException("the port must be 1 to 65535, got " + port);
            return new URI("ws", null, hp.substring(0, colon).replaceAll("^\\[|\\]$", ""), port, Protocol.PATH, null, null);
        } catch (NumberFormatException | java.net.URISyntaxException e) {
            throw new IllegalArgumentException("expected HOST:PORT, got " + hostPort);
        }
    }

    /** Connects, waiting at most {@code timeout}; an unreachable server is an {@link IOException} of one line. */
    public static OnlineClient connect(URI uri, Listener listener, Duration timeout) throws IOException {
        Receiver receiver = new Receiver(listener);
        try {
            WebSocket ws = SHARED.newWebSocketBuilder().connectTimeout(timeout).buildAsync(uri, receiver)
                    .get(timeout.toMillis() + 1000, TimeUnit.MILLISECONDS);
            OnlineClient c = new OnlineClient(ws);
            receiver.client = c;
            return c;
        } catch (ExecutionException e) {
            Throwable cause = e.getCause();
            while (cause.getCause() != null && cause.getMessage() == null) cause = cause.getCause();
            throw new IOException("cannot reach the server at " + uri.getHost() + ":" + uri.getPort() + ": "
                    + (cause.getMessage() != null ? cause.getMessage() : cause.getClass().getSimpleName()), e);
        } catch (TimeoutException e) {
            throw new IOException("cannot reach the server at " + uri.getHost() + ":" + uri.getPort() + ": no answer in "
                    + timeout.toSeconds() + " s", e);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IOException("interrupted while connecting", e);
        }
    }

    public void send(ClientMessage message) {
        sendText(ClientMessages.write(message));
    }

    /** Sends raw text (tests send malformed messages this way). Messages leave in the order given. */
    public void sendText(String text) {
        synchronized (sendLock) {
            if (closed) return;
            sending = sending.handle((v, e) -> null).thenCompose(v -> socket.sendText(text, true));
        }
    }

    public boolean isOpen() {
        return !closed && !socket.isOutputClosed() && !socket.isInputClosed();
    }

    /** Closes the connection politely (1000). */
    @Override
    public void close() {
        synchronized (sendLock) {
            if (closed) return;
            closed = true;
            sending.handle((v, e) -> null).thenCompose(v -> socket.sendClose(WebSocket.NORMAL_CLOSURE, "bye"));
        }
    }

    /** Drops the connection at once, without a closing handshake (as a crash or a lost network would). */
    public void abort() {
        closed = true;
        socket.abort();
    }

    private static final class Receiver implements WebSocket.Listener {
        private final Listener listener;
        private final StringBuilder partial = new StringBuilder();
        volatile OnlineClient client;
        private boolean ended;

        Receiver(Listener listener) {
            this.listener = listener;
        }

        @Override
        public CompletionStage<?> onText(WebSocket ws, CharSequence data, boolean last) {
            partial.append(data);
            if (last) {
                String text = partial.toString();
                partial.setLength(0);
                try {
                    listener.onMessage(Json.parse(text));
                } catch (ProtocolException e) {
                    // The server sent something that is not a message: ignored (a newer server adds only fields).
                }
            }
            ws.request(1);
            return null;
        }

        @Override
        public CompletionStage<?> onClose(WebSocket ws, int statusCode, String reason) {
            end("the server closed the connection (" + statusCode + (reason == null || reason.isEmpty() ? "" : ": " + reason) + ")");
            return null;
        }

        @Override
        public void onError(WebSocket ws, Throwable error) {
            end("the connection was lost: " + (error.getMessage() != null ? error.getMessage() : error.getClass().getSimpleName()));
        }

        private synchronized void end(String reason) {
            if (ended) return;
            ended = true;
            OnlineClient c = client;
            if (c != null) c.closed = true;
            listener.onClosed(reason);
        }
    }
}
