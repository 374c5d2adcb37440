package minigolf.app;

import java.nio.ByteBuffer;
import java.nio.IntBuffer;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.EnumMap;
import java.util.Map;
import minigolf.app.SoundSynth.Sound;
import minigolf.game.AudioSettings;
import org.lwjgl.openal.AL;
import org.lwjgl.openal.AL10;
import org.lwjgl.openal.ALC;
import org.lwjgl.openal.ALC10;
import org.lwjgl.openal.ALCCapabilities;

import static org.lwjgl.openal.AL10.*;

/**
 * Plays the synthesised sounds ({@link SoundSynth}) through OpenAL (LWJGL's OpenAL Soft). With no
 * audio device the game is silent: one line on the log and every call does nothing. On Linux the
 * device is opened only where there is something to play to (a sound card, a PulseAudio or
 * PipeWire socket, or an OpenAL Soft config named by {@code ALSOFT_CONF}), so ALSA's complaints
 * never reach a player's terminal on a machine without sound. Call from one thread (the render thread).
 */
public final class Sounds implements AutoCloseable {
    /** Effects playing at once; a new one takes the source that has played longest. */
    private static final int VOICES = 12;

    private long device;
    private long context;
    private final Map<Sound, Integer> buffers = new EnumMap<>(Sound.class);
    private final int[] voices = new int[VOICES];
    private int nextVoice;
    private int ambienceSource;
    /** The world whose loop plays, and its buffer (0 while Meadowbrook's of {@link #buffers} plays). */
    private minigolf.theme.Theme.Ambience ambience = minigolf.theme.Theme.Ambience.BIRDS;
    private int worldAmbience;
    private AudioSettings volumes;

    private Sounds(AudioSettings volumes) {
        this.volumes = volumes;
    }

    /** Opens the default device, or returns a silent player (and logs one line) when there is none. */
    public static Sounds open(AudioSettings volumes) {
        Sounds s = new Sounds(volumes);
        String why = s.openDevice();
        if (why != null) System.err.println("minigolf: no sound (" + why + "); the game is silent");
        return s;
    }

    /** Why OpenAL should not even be asked for a device, or null when it may. */
    static String reasonToStaySilent(Map<String, String> env, boolean linux) {
        if (Boolean.getBoolean("minigolf.noSound")) return "switched off by -Dminigolf.noSound";
        if (!linux || env.get("ALSOFT_CONF") != null) return null;
        if (isNonEmptyDirectory(Path.of("/dev/snd"))) return null;
        String runtime = env.get("XDG_RUNTIME_DIR");
        if (runtime != null && (Files.exists(Path.of(runtime, "pulse", "native")) || Files.exists(Path.of(runtime, "pipewire-0")))) {
            return null;
        }
        if (env.get("PULSE_SERVER") != null) return null;
        return "no sound card or sound server";
    }

    private static boolean isNonEmptyDirectory(Path p) {
        try (var s = Files.list(p)) {
            return s.findAny().isPresent();
        } catch (Exception e) {
            return false;
        }
    }

    private String openDevice() {
        String why = reasonToStaySilent(System.getenv(), System.getProperty("os.name", "").toLowerCase().contains("linux"));
        if (why != null) return why;
        try {
            device = ALC10.alcOpenDevice((ByteBuffer) null);
            if (device == 0) return "no audio device";
            ALCCapabilities caps = ALC.createCapabilities(device);
            context = ALC10.alcCreateContext(device, (IntBuffer) null);
            if (context == 0 || !ALC10.alcMakeContextCurrent(context)) {
                close();
                return "cannot start OpenAL on the audio device";
            }
            AL.createCapabilities(caps);
            for (Sound s : Sound.values()) {
                int b = alGenBuffers();
                alBufferData(b, AL_FORMAT_MONO16, SoundSynth.make(s), SoundSynth.RATE);
                buffers.put(s, b);
            }
            for (int i = 0; i < VOICES; i++) voices[i] = alGenSources();
            ambienceSource = alGenSources();
            alSourcei(ambienceSource, AL_BUFFER, buffers.get(Sound.AMBIENCE));
            alSourcei(ambienceSource, AL_LOOPING, AL_TRUE);
            applyAmbience();
            if (alGetError() != AL_NO_ERROR) {
                close();
                return "OpenAL error while loading the sounds";
            }
            return null;
        } catch (RuntimeException | UnsatisfiedLinkError e) {
            close();
            return "OpenAL is not available: " + e.getMessage();
        }
    }

    public boolean isSilent() {
        return context == 0;
    }

    public AudioSettings volumes() {
        return volumes;
    }

    public void setVolumes(AudioSettings v) {
        volumes = v;
        applyAmbience();
    }

    /** Plays this world's background loop instead (the ambience volume still decides how loud). */
    public void setAmbience(minigolf.theme.Theme.Ambience a) {
        if (isSilent() || a == ambience) return;
        ambience = a;
        alSourceStop(ambienceSource);
        alSourcei(ambienceSource, AL_BUFFER, 0);
        if (worldAmbience != 0) alDeleteBuffers(worldAmbience);
        worldAmbience = alGenBuffers();
        alBufferData(worldAmbience, AL_FORMAT_MONO16, SoundSynth.ambience(a), SoundSynth.RATE);
        alSourcei(ambienceSource, AL_BUFFER, worldAmbience);
        applyAmbience();
    }

    private void applyAmbience() {
        if (isSilent()) return;
        float gain = (float) (volumes.master() * volumes.ambience() * 0.25);
        alSourcef(ambienceSource, AL_GAIN, gain);
        int state = alGetSourcei(ambienceSource, AL_SOURCE_STATE);
        if (gain > 0 && state != AL_PLAYING) alSourcePlay(ambienceSource);
        if (gain == 0 && state == AL_PLAYING) alSourceStop(ambienceSource);
    }

    /** Plays an effect at a loudness of 0 to 1 (times the effects and master volumes) and a pitch factor. */
    public void play(Sound s, double loudness, double pitch) {
        if (isSilent() || s == Sound.AMBIENCE) return;
        float gain = (float) (Math.max(0, Math.min(1, loudness)) * volumes.effects() * volumes.master());
        if (gain <= 0) return;
        int src = voices[nextVoice];
        nextVoice = (nextVoice + 1) % VOICES;
        alSourceStop(src);
        alSourcei(src, AL_BUFFER, buffers.get(s));
        alSourcef(src, AL_GAIN, gain);
        alSourcef(src, AL_PITCH, (float) Math.max(0.5, Math.min(2, pitch)));
        alSourcePlay(src);
    }

    @Override
    public void close() {
        if (context != 0) {
            for (int v : voices) if (v != 0) AL10.alDeleteSources(v);
            if (ambienceSource != 0) AL10.alDeleteSources(ambienceSource);
            if (worldAmbience != 0) AL10.alDeleteBuffers(worldAmbience);
            for (int b : buffers.values()) AL10.alDeleteBuffers(b);
            ALC10.alcMakeContextCurrent(0);
            ALC10.alcDestroyContext(context);
            context = 0;
        }
        if (device != 0) {
            ALC10.alcCloseDevice(device);
            device = 0;
        }
        buffers.clear();
    }
}
